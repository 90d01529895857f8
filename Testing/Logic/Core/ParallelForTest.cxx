// parallelFor on the worker pool: every index once, fixed ranges' results in order, nested calls, failures, the pool's threads lent
// again rather than new ones started for each call, and a forked child's own pool (no allocation
// once the pool has grown: PoolAllocationTest.cxx).
#include "Core/ParallelFor.h"

#include <gtest/gtest.h>

#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace slicemesh;

TEST(ParallelFor, CallsEveryIndexOnceOnAnyNumberOfThreads)
{
  for (unsigned int threads : { 1u, 2u, 3u, 8u })
  {
    std::vector<std::atomic<int>> calls(1000);
    parallelFor(calls.size(), threads, [&](std::size_t i) { ++calls[i]; });
    for (std::size_t i = 0; i < calls.size(); ++i)
      ASSERT_EQ(calls[i].load(), 1) << "index " << i << " on " << threads << " threads";
  }
}

TEST(ParallelFor, FixedRangeResultsComeBackInRangeOrderOnAnyNumberOfThreads)
{
  // 10 ranges of 1000 (the last 500) of 9500 indices: each range's result starts value-initialized
  // and holds what its body put there, whatever the threads.
  struct Sum
  {
    std::size_t first = 0, total = 0, calls = 0;
  };
  for (unsigned int threads : { 1u, 2u, 8u })
  {
    const std::vector<Sum> sums = fixedRangeResults<Sum>(9500, 1000, threads,
                                                         [](Sum& sum, std::size_t first, std::size_t last)
                                                         {
                                                           ++sum.calls;
                                                           sum.first = first;
                                                           for (std::size_t i = first; i < last; ++i)
                                                             sum.total += i;
                                                         });
    ASSERT_EQ(sums.size(), 10u) << threads;
    for (std::size_t r = 0; r < sums.size(); ++r)
    {
      const std::size_t first = 1000 * r, last = std::min<std::size_t>(9500, first + 1000);
      EXPECT_EQ(sums[r].calls, 1u) << threads << " " << r;
      EXPECT_EQ(sums[r].first, first) << threads << " " << r;
      EXPECT_EQ(sums[r].total, (first + last - 1) * (last - first) / 2) << threads << " " << r;
    }
  }
}

TEST(ParallelFor, NestedCallsFinishWhenEveryThreadIsBusy)
{
  // Outer work on 4 threads, each item running inner loops on 4 threads: the pool's threads are all
  // busy with outer items, so the inner calls' requests can wait unanswered; each caller must then
  // do its inner work itself and still return.
  std::atomic<long> sum{ 0 };
  parallelFor(16, 4,
              [&](std::size_t outer)
              {
                for (int round = 0; round < 20; ++round)
                  parallelForRanges(
                    5000, 4,
                    [&](std::size_t first, std::size_t last)
                    {
                      long local = 0;
                      for (std::size_t i = first; i < last; ++i)
                        local += static_cast<long>(outer + i % 3);
                      sum += local;
                    },
                    256);
              });
  long expected = 0;
  for (long outer = 0; outer < 16; ++outer)
    for (long i = 0; i < 5000; ++i)
      expected += 20 * (outer + i % 3);
  EXPECT_EQ(sum.load(), expected);
}

TEST(ParallelFor, RethrowsTheSmallestFailingIndexAfterTryingEveryIndex)
{
  std::atomic<int> attempted{ 0 };
  try
  {
    parallelFor(200, 4,
                [&](std::size_t i)
                {
                  ++attempted;
                  if (i == 37 || i == 150)
                    throw std::runtime_error(std::to_string(i));
                });
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_STREQ(e.what(), "37");
  }
  EXPECT_EQ(attempted.load(), 200);
}

TEST(ParallelFor, LendsThePoolsThreadsInsteadOfStartingNewOnes)
{
  // Fifty calls on two threads: with a thread started per call they would run on up to 51 distinct
  // threads; the pool lends the same helper every time. Threads are told apart by the kernel's
  // thread id, which is not handed out again soon (std::thread::id often is, once one has ended).
  std::mutex lock;
  std::set<long> used;
  for (int call = 0; call < 50; ++call)
    parallelFor(8, 2,
                [&](std::size_t)
                {
                  std::this_thread::sleep_for(std::chrono::microseconds(200));
                  const std::lock_guard<std::mutex> guard(lock);
                  used.insert(static_cast<long>(syscall(SYS_gettid)));
                });
  EXPECT_GE(used.size(), 1u);
  // The caller, plus at most the helpers the pool holds: no more than the most any call of this
  // process asked for (8 in the tests above).
  EXPECT_LE(used.size(), 9u);
}

TEST(ParallelFor, AChildForkedWhileThePoolIsBusyHasAPoolOfItsOwn)
{
  // The pool's lock is taken and released all the time while another thread runs short calls; a
  // child forked at such a moment would wait for it forever if it used the parent's pool.
  // The pool is started before the first fork: a child forked while the busy thread was still
  // starting it (the first call in this process) would wait forever on the start's guard instead,
  // which is no case of this test (seen once in CI on a loaded machine).
  parallelFor(4, 2, [](std::size_t) {});
  std::atomic<bool> stop{ false };
  std::thread busy(
    [&]
    {
      while (!stop)
        parallelFor(4, 2, [](std::size_t) {});
    });
  int hung = 0, failed = 0;
  for (int child = 0; child < 40; ++child)
  {
    const pid_t pid = fork();
    if (pid == 0)
    {
      std::atomic<int> calls{ 0 };
      parallelFor(64, 2, [&](std::size_t) { ++calls; });
      _exit(calls == 64 ? 0 : 1);
    }
    ASSERT_GT(pid, 0);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (waitpid(pid, &status, WNOHANG) == 0)
    {
      if (std::chrono::steady_clock::now() > deadline)
      {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        ++hung;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    failed += WIFEXITED(status) && WEXITSTATUS(status) != 0;
    if (hung > 0)
      break; // one is enough to fail, and each costs the deadline
  }
  stop = true;
  busy.join();
  EXPECT_EQ(hung, 0);
  EXPECT_EQ(failed, 0);
}

#include "Core/WorkerPool.h"

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace slicemesh
{
namespace
{

/** One call of runOnPool: the work its helpers run and how many of them are running it now. */
struct Job
{
  PoolWork work;
  std::size_t running = 0;
};

class WorkerPool
{
public:
  void run(std::size_t helpers, PoolWork work)
  {
    Job job{ work };
    // Whichever way this call ends, no request for the job is left queued and no helper is still
    // running it once the job (on this stack) is gone.
    struct Withdraw
    {
      WorkerPool& pool;
      Job& job;
      ~Withdraw()
      {
        std::unique_lock<std::mutex> lock(pool.m_Lock);
        pool.m_Requests.erase(std::remove(pool.m_Requests.begin(), pool.m_Requests.end(), &job), pool.m_Requests.end());
        pool.m_Finished.wait(lock, [this] { return job.running == 0; });
      }
    } withdraw{ *this, job };
    if (helpers > 0)
    {
      {
        const std::lock_guard<std::mutex> lock(m_Lock);
        grow(helpers);
        // No more requests than threads to take them: the caller does the rest itself.
        m_Requests.insert(m_Requests.end(), std::min(helpers, m_Threads.size()), &job);
      }
      if (helpers == 1)
        m_Requested.notify_one();
      else
        m_Requested.notify_all();
    }
    work();
  }

private:
  /** At least `helpers` threads, as far as the system gives them (a thread it refuses leaves the
   *  work to the threads there are). Called with m_Lock held. */
  void grow(std::size_t helpers)
  {
    try
    {
      while (m_Threads.size() < helpers)
        m_Threads.emplace_back([this] { serve(); });
    }
    catch (const std::system_error&)
    {
    }
  }

  void serve()
  {
    std::unique_lock<std::mutex> lock(m_Lock);
    for (;;)
    {
      m_Requested.wait(lock, [this] { return !m_Requests.empty(); });
      Job* job = m_Requests.front();
      m_Requests.erase(m_Requests.begin()); // a few entries: no more than the pool's threads per call
      ++job->running;
      lock.unlock();
      job->work();
      lock.lock();
      if (--job->running == 0)
        m_Finished.notify_all();
    }
  }

  std::mutex m_Lock;
  std::condition_variable m_Requested; // a request was queued
  std::condition_variable m_Finished;  // a job's last running helper returned
  std::vector<Job*> m_Requests;        // one entry per helper a job asked for; keeps its capacity
  std::vector<std::thread> m_Threads;
};

/** The process's pool. Never destroyed: its threads wait for requests until the process ends, and no
 *  exit path (including one taken on a worker thread) has to join them first. */
std::atomic<WorkerPool*> processPool{ nullptr };

/** A new pool for the process: the first, and one for every child process (fork), which has only
 *  the thread that forked while the pool's lock may have been held by another at that moment (the
 *  parent's pool, copied into the child, is left as it was and never used there). */
void startPool()
{
  processPool.store(new WorkerPool);
}

WorkerPool& pool()
{
  static const bool started = (startPool(), pthread_atfork(nullptr, nullptr, &startPool), true);
  static_cast<void>(started);
  return *processPool.load();
}

} // namespace

void runOnPool(std::size_t helpers, PoolWork work)
{
  pool().run(helpers, work);
}

} // namespace slicemesh

// The worker pool allocates nothing per call once it has grown. A program of its own: it counts
// every operator new of the process, which would take new/delete checking away from the sanitizer
// run of the other Logic tests.
#include "Core/ParallelFor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
/** Allocations through operator new, on any thread. */
std::atomic<long> allocations{ 0 };
} // namespace

void* operator new(std::size_t size)
{
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}

void operator delete(void* p) noexcept
{
  std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

TEST(WorkerPool, ACallAllocatesNothingOnceThePoolHasGrown)
{
  // A thread inside the allocator when another forks can leave the child's allocator locked
  // (AddressSanitizer's runtime does): the pool's own calls must never be that thread. With the
  // work held as a std::function (its captures on the heap) and a deque of requests, 1000 calls
  // made 1047 allocations.
  std::atomic<long> sum{ 0 };
  auto add = [&](std::size_t i) { sum += static_cast<long>(i); };
  for (int call = 0; call < 10; ++call)
    slicemesh::parallelFor(64, 4, add);
  const long before = allocations.load();
  for (int call = 0; call < 1000; ++call)
    slicemesh::parallelFor(64, 4, add);
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_EQ(sum.load(), 1010L * (63 * 64 / 2));
}

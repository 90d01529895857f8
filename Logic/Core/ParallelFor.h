// Runs independent pieces of work on several threads: structures, connected pieces, slabs, ranges of
// a mesh's vertices. Results
// go into slots chosen by index, never by finishing order, so the output does not depend on the
// number of threads.
#ifndef ParallelFor_h
#define ParallelFor_h

#include "Core/WorkerPool.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace slicemesh
{

/** The most threads a call that asks for every core (0) gets, for the whole process: 0 (the
 *  default) for every core the machine reports. A program that promises to stay within a number of
 *  threads (the CLI's --threads) sets it once, before any work. */
inline std::atomic<unsigned int>& everyCoreLimit()
{
  static std::atomic<unsigned int> limit{ 0 };
  return limit;
}

/** The number of threads to use for `asked` (0: every core, within everyCoreLimit; at least 1). */
inline unsigned int threadCount(unsigned int asked)
{
  if (asked > 0)
    return asked;
  const unsigned int limit = everyCoreLimit().load();
  return limit > 0 ? limit : std::max(1u, std::thread::hardware_concurrency());
}

/** Calls body(i) for every i in [0, count), on up to threadCount(threads) threads (the calling one
 *  and threads lent by the process's pool, Core/WorkerPool.h), each i exactly once, in no
 *  particular order. If calls throw, every i is still attempted and the exception of the smallest
 *  such i is rethrown. */
template <typename Body>
void parallelFor(std::size_t count, unsigned int threads, Body&& body)
{
  const std::size_t workers = std::min<std::size_t>(threadCount(threads), count);
  if (workers <= 1)
  {
    std::exception_ptr first;
    for (std::size_t i = 0; i < count; ++i)
      try
      {
        body(i);
      }
      catch (...)
      {
        if (!first)
          first = std::current_exception();
      }
    if (first)
      std::rethrow_exception(first);
    return;
  }
  std::atomic<std::size_t> next{ 0 };
  std::mutex failureLock;
  std::size_t failedIndex = count;
  std::exception_ptr failure;
  auto work = [&]
  {
    for (std::size_t i = next++; i < count; i = next++)
      try
      {
        body(i);
      }
      catch (...)
      {
        const std::lock_guard<std::mutex> lock(failureLock);
        if (i < failedIndex)
        {
          failedIndex = i;
          failure = std::current_exception();
        }
      }
  };
  runOnPool(workers - 1, work);
  if (failure)
    std::rethrow_exception(failure);
}

/** Calls body(begin, end) on consecutive ranges covering [0, count), on up to threadCount(threads)
 *  threads: for per-element work too small to schedule one element at a time (every vertex of a
 *  mesh). Each range holds at least minimumRange elements, so small counts stay on one thread. */
template <typename Body>
void parallelForRanges(std::size_t count, unsigned int threads, Body&& body, std::size_t minimumRange = 4096)
{
  const std::size_t ranges =
    std::max<std::size_t>(1, std::min<std::size_t>(4 * threadCount(threads), count / std::max<std::size_t>(1, minimumRange)));
  const std::size_t step = (count + ranges - 1) / ranges;
  parallelFor(ranges, threads, [&](std::size_t r) { body(std::min(count, r * step), std::min(count, (r + 1) * step)); });
}

/** Calls body(i, threads) for each i of `items`: the large ones (isLarge(i)) one after another, each
 *  on up to threadCount(threads) threads for its own loops, then the others side by side, each on
 *  one. For items of very different sizes (a large piece among specks), where one thread an item
 *  would leave the large one alone on its thread. */
template <typename IsLarge, typename Body>
void largeOnesFirst(const std::vector<std::size_t>& items, unsigned int threads, IsLarge&& isLarge, Body&& body)
{
  std::vector<std::size_t> small;
  for (std::size_t i : items)
    if (isLarge(i))
      body(i, threads);
    else
      small.push_back(i);
  parallelFor(small.size(), threads, [&](std::size_t k) { body(small[k], 1u); });
}

/** How many ranges of `rangeSize` cover [0, count) (the last one may be shorter). */
inline std::size_t fixedRangeCount(std::size_t count, std::size_t rangeSize)
{
  return (count + rangeSize - 1) / rangeSize;
}

/** Calls body(r, first, last) for the r-th range of `rangeSize` of [0, count), on up to
 *  threadCount(threads) threads. The ranges follow from the count alone, not from the threads: a
 *  sum kept per range and added in range order is the same whatever the number of threads. */
template <typename Body>
void parallelForFixedRanges(std::size_t count, std::size_t rangeSize, unsigned int threads, Body&& body)
{
  parallelFor(fixedRangeCount(count, rangeSize), threads,
              [&](std::size_t r) { body(r, r * rangeSize, std::min(count, (r + 1) * rangeSize)); });
}

/** parallelForFixedRanges for sums: body(result, first, last) fills a Result of the range's own
 *  (value-initialized), held by its thread until the range ends; the results come back in range
 *  order. (Ranges that add into neighbouring elements of one shared array as they go keep passing
 *  cache lines between the cores: a smoothing's volume sums took a third longer so.) */
template <typename Result, typename Body>
std::vector<Result> fixedRangeResults(std::size_t count, std::size_t rangeSize, unsigned int threads, Body&& body)
{
  std::vector<Result> results(fixedRangeCount(count, rangeSize));
  parallelForFixedRanges(count, rangeSize, threads,
                         [&](std::size_t r, std::size_t first, std::size_t last)
                         {
                           Result result{};
                           body(result, first, last);
                           results[r] = std::move(result);
                         });
  return results;
}

} // namespace slicemesh

#endif

// Threads kept for the whole run, which parallelFor lends to its calls instead of starting new ones.
#ifndef WorkerPool_h
#define WorkerPool_h

#include <cstddef>
#include <type_traits>

namespace slicemesh
{

/** A callable of the caller's, borrowed for a call of runOnPool (which returns only once no thread
 *  runs it any more): unlike std::function it never allocates, so a call of the pool allocates
 *  nothing once the pool has grown. A process that forks while another thread is inside the
 *  allocator may leave the child's allocator locked (AddressSanitizer's runtime does); the pool's
 *  own calls are then never the cause. */
class PoolWork
{
public:
  /** Not for a PoolWork itself: that is copied (a template taking any lvalue would otherwise wrap
   *  the copy's source instead). */
  template <typename Work, typename = std::enable_if_t<!std::is_same_v<std::remove_cv_t<Work>, PoolWork>>>
  PoolWork(Work& work) // implicit: parallelFor passes its lambda as it is
    : m_Work(&work), m_Call([](void* w) { (*static_cast<Work*>(w))(); })
  {
  }
  void operator()() const { m_Call(m_Work); }

private:
  void* m_Work;
  void (*m_Call)(void*);
};

/** Runs `work` on the calling thread and on up to `helpers` threads of the process's pool at once,
 *  and returns once every call of it has returned. `work` must not throw, and must be safe to run
 *  several times side by side: each call takes what is left to do (an atomic counter) and returns
 *  when nothing is.
 *
 *  Why a pool: a thread started for each call cost about 60 microseconds on the project's machine,
 *  often more than a range of a mesh's vertices took, so in a loop of short calls (the smoothing's
 *  200 steps) the calling thread had done nearly all of it before the new thread began.
 *
 *  Calls may nest (work that calls runOnPool). A helper that is busy never holds up the caller: the
 *  caller does the work itself, takes back the requests no helper has picked up, and waits only for
 *  helpers already running `work`, which never wait for anything queued. The pool grows to the most
 *  helpers any call asked for, and its threads last until the process ends. A child process (fork)
 *  starts a pool of its own the first time it asks. */
void runOnPool(std::size_t helpers, PoolWork work);

} // namespace slicemesh

#endif

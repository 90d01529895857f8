#include "Core/WorkerPool.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace slicemesh
{
namespace
{

/** One call of runOnPool: the work its helpers run and how many of them are running it now. */
struct Job
{
  const std::function<void()>* work = nullptr;
  std::size_t running = 0;
};

class WorkerPool
{
public:
  void run(std::size_t helpers, const std::function<void()>& work)
  {
    Job job;
    job.work = &work;
    if (helpers > 0)
    {
      {
        const std::lock_guard<std::mutex> lock(m_Lock);
        while (m_Threads.size() < helpers)
          m_Threads.emplace_back([this] { serve(); });
        m_Requests.insert(m_Requests.end(), helpers, &job);
      }
      if (helpers == 1)
        m_Requested.notify_one();
      else
        m_Requested.notify_all();
    }
    work();
    if (helpers == 0)
      return;
    std::unique_lock<std::mutex> lock(m_Lock);
    m_Requests.erase(std::remove(m_Requests.begin(), m_Requests.end(), &job), m_Requests.end());
    m_Finished.wait(lock, [&job] { return job.running == 0; });
  }

private:
  void serve()
  {
    std::unique_lock<std::mutex> lock(m_Lock);
    for (;;)
    {
      m_Requested.wait(lock, [this] { return !m_Requests.empty(); });
      Job* job = m_Requests.front();
      m_Requests.pop_front();
      ++job->running;
      lock.unlock();
      (*job->work)();
      lock.lock();
      if (--job->running == 0)
        m_Finished.notify_all();
    }
  }

  std::mutex m_Lock;
  std::condition_variable m_Requested; // a request was queued
  std::condition_variable m_Finished;  // a job's last running helper returned
  std::deque<Job*> m_Requests;         // one entry per helper a job asked for
  std::vector<std::thread> m_Threads;
};

} // namespace

void runOnPool(std::size_t helpers, const std::function<void()>& work)
{
  // Never destroyed: its threads wait for requests until the process ends, and no exit path
  // (including one taken on a worker thread) has to join them first.
  static WorkerPool* const pool = new WorkerPool;
  pool->run(helpers, work);
}

} // namespace slicemesh

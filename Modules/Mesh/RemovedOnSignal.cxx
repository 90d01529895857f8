#include "RemovedOnSignal.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <unistd.h>

namespace slicemesh
{
namespace
{

constexpr std::size_t longestPath = 4096;
constexpr int tableSlots = 64;

/** The files to remove, read by the handler: only a slot marked in use (after its path is written)
 *  is read, so the handler needs no lock (a lock is not safe in a signal handler). */
struct WatchedFile
{
  std::atomic<bool> inUse{ false };
  char path[longestPath];
};

/** Slots by the table of tableSlots, a table added when all are in use (never freed: the handler may be
 *  walking them): a run of one mesh per label holds every label's temporary file until all are
 *  written, and an atlas has hundreds. */
struct WatchedTable
{
  WatchedFile files[tableSlots];
  std::atomic<WatchedTable*> next{ nullptr };
};
WatchedTable watched;

constexpr int stoppingSignals[] = { SIGTERM, SIGINT, SIGHUP };

extern "C" void removeWatchedFiles(int signal)
{
  for (WatchedTable* table = &watched; table; table = table->next.load())
    for (WatchedFile& file : table->files)
      if (file.inUse.load())
        ::unlink(file.path); // async-signal-safe
  // The signal's own course: the default action (the process ends as if it had not been caught).
  struct sigaction usual{};
  usual.sa_handler = SIG_DFL;
  ::sigemptyset(&usual.sa_mask);
  ::sigaction(signal, &usual, nullptr);
  ::raise(signal);
}

void installHandlersOnce()
{
  static std::once_flag installed;
  std::call_once(installed,
                 []
                 {
                   for (int signal : stoppingSignals)
                   {
                     struct sigaction current{};
                     if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL ||
                         (current.sa_flags & SA_SIGINFO))
                       continue; // the process handles or ignores it itself
                     struct sigaction handler{};
                     handler.sa_handler = removeWatchedFiles;
                     ::sigemptyset(&handler.sa_mask);
                     for (int other : stoppingSignals) // one handler at a time
                       ::sigaddset(&handler.sa_mask, other);
                     ::sigaction(signal, &handler, nullptr);
                   }
                 });
}

/** Slots are taken and given back under this lock (never taken by the handler). */
std::mutex slotLock;

} // namespace

RemovedOnSignal::RemovedOnSignal(const std::string& path)
{
  if (path.size() >= longestPath)
    return;
  installHandlersOnce();
  const std::lock_guard<std::mutex> lock(slotLock);
  int slot = 0;
  for (WatchedTable* table = &watched;; table = table->next.load())
  {
    for (WatchedFile& file : table->files)
    {
      if (!file.inUse.load())
      {
        std::memcpy(file.path, path.c_str(), path.size() + 1);
        file.inUse.store(true);
        m_Slot = slot;
        return;
      }
      ++slot;
    }
    if (!table->next.load())
      table->next.store(new WatchedTable); // complete before the handler can reach it
  }
}

RemovedOnSignal::~RemovedOnSignal()
{
  if (m_Slot < 0)
    return;
  const std::lock_guard<std::mutex> lock(slotLock);
  WatchedTable* table = &watched;
  for (int skipped = m_Slot / tableSlots; skipped > 0; --skipped)
    table = table->next.load();
  table->files[m_Slot % tableSlots].inUse.store(false);
}

} // namespace slicemesh

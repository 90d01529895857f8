// RemovedOnSignal: a file being written is removed when the run is stopped by SIGTERM or SIGINT, and
// kept once it is no longer watched; the signal still ends the process. Each case runs in a child
// process (fork) so that the signal ends the child, not the tests.
#include "RemovedOnSignal.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace
{

fs::path freshFile(const std::string& name)
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "RemovedOnSignal";
  fs::create_directories(folder);
  const fs::path file = folder / name;
  std::ofstream(file) << "half written";
  return file;
}

/** Runs `child` in a child process, which then stops itself with `signal`; the signal that ended it
 *  (0 if it exited). */
template <typename Child>
int endedBy(int signal, Child child)
{
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    child();
    ::raise(signal);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

TEST(RemovedOnSignal, AFileBeingWrittenIsRemovedWhenTheRunIsStopped)
{
  for (int signal : { SIGTERM, SIGINT })
  {
    const fs::path file = freshFile(".out.partial-" + std::to_string(signal) + ".vtp");
    const fs::path other = freshFile("other-" + std::to_string(signal) + ".vtp");
    const int ended = endedBy(signal,
                              [&]
                              {
                                static slicemesh::RemovedOnSignal watched(file.string());
                                static slicemesh::RemovedOnSignal alsoWatched(other.string());
                              });
    EXPECT_EQ(ended, signal); // the signal still ends the process
    EXPECT_FALSE(fs::exists(file)) << signal;
    EXPECT_FALSE(fs::exists(other)) << signal;
  }
}

TEST(RemovedOnSignal, AnyNumberOfFilesAreWatchedAtOnce)
{
  // A run of one mesh per label holds every label's temporary until all are written: past 64 files
  // the others were not watched, and a stopped atlas run left them.
  std::vector<fs::path> files;
  for (int n = 0; n < 200; ++n)
    files.push_back(freshFile(".label-" + std::to_string(n) + ".partial.vtp"));
  const int ended = endedBy(SIGTERM,
                            [&]
                            {
                              static std::vector<std::unique_ptr<slicemesh::RemovedOnSignal>> watched;
                              for (const fs::path& file : files)
                                watched.push_back(std::make_unique<slicemesh::RemovedOnSignal>(file.string()));
                            });
  EXPECT_EQ(ended, SIGTERM);
  for (const fs::path& file : files)
    EXPECT_FALSE(fs::exists(file)) << file;
}

TEST(RemovedOnSignal, AFileNoLongerWatchedIsKept)
{
  const fs::path file = freshFile("finished.vtp");
  const int ended = endedBy(SIGTERM, [&] { slicemesh::RemovedOnSignal watched(file.string()); });
  EXPECT_EQ(ended, SIGTERM);
  EXPECT_TRUE(fs::exists(file));
}

TEST(RemovedOnSignal, AProcessThatIgnoresTheSignalKeepsDoingSo)
{
  // SliceMesh loaded into a program with its own handling of the signal leaves it alone.
  const fs::path file = freshFile(".ignored.partial.vtp");
  const int ended = endedBy(SIGTERM,
                            [&]
                            {
                              ::signal(SIGTERM, SIG_IGN);
                              static slicemesh::RemovedOnSignal watched(file.string());
                            });
  EXPECT_EQ(ended, 0); // ignored: the child exited on its own
  EXPECT_TRUE(fs::exists(file));
}

} // namespace

// --threads: the same input gives the same files, byte for byte, on 1, 2 and 8 threads: one mesh of
// a mask with several pieces, and one mesh per label.
#include "CLITestSupport.h"
#include "Core/ParallelFor.h"
#include "ExitCodes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <set>
#include <thread>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

/** Three labels on 1 x 1 x 1.5 mm voxels: two balls (label 1, two pieces), a torus (label 2) and a
 *  box that touches one ball (label 3). */
fs::path threeLabels(const fs::path& folder)
{
  const fs::path path = folder / "labels.mha";
  writeMetaImage(path, { 48, 40, 24 }, { 1.0, 1.0, 1.5 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   const double x = i, y = j, z = 1.5 * k;
                   auto ball = [&](double cx, double cy, double cz, double r)
                   { return (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) <= r * r; };
                   if (ball(10, 10, 12, 7) || ball(10, 28, 18, 6))
                     return 1;
                   const double ring = std::hypot(x - 32, y - 20) - 9.0;
                   if (ring * ring + (z - 18) * (z - 18) <= 9.0)
                     return 2;
                   if (i >= 17 && i <= 24 && j >= 6 && j <= 14 && k >= 4 && k <= 12)
                     return 3;
                   return 0;
                 });
  return path;
}

TEST(Threads, TheFilesAreTheSameOnOneTwoAndEightThreads)
{
  const fs::path folder = freshFolder("Threads");
  const fs::path input = threeLabels(folder);
  for (const std::string& mode : { std::string(""), std::string("--splitLabels ") })
  {
    std::string first;
    std::vector<std::string> firstLabels;
    for (int threads : { 1, 2, 8 })
    {
      SCOPED_TRACE(mode + "--threads " + std::to_string(threads));
      const fs::path out = folder / ("out-" + std::to_string(threads) + (mode.empty() ? "" : "-split"));
      fs::create_directories(out);
      const std::string labels = mode.empty() ? "" : "--outputDirectory " + quoted((out / "labels").string()) + " ";
      const RunResult r = runSliceMesh(mode + labels + "--threads " + std::to_string(threads) + " " +
                                       quoted(input.string()) + " " + quoted((out / "mesh.vtp").string()));
      ASSERT_EQ(r.exitCode, cli::Success) << r.err;
      const std::string mesh = fileText(out / "mesh.vtp");
      ASSERT_GT(mesh.size(), 1000u);
      std::vector<std::string> perLabel;
      if (!mode.empty())
        for (const char* name : { "001_Label_1.vtp", "002_Label_2.vtp", "003_Label_3.vtp" })
          perLabel.push_back(fileText(out / "labels" / name));
      if (threads == 1)
      {
        first = mesh;
        firstLabels = perLabel;
        continue;
      }
      EXPECT_TRUE(mesh == first) << "the merged mesh differs from the one-thread run";
      EXPECT_TRUE(perLabel == firstLabels) << "a label's mesh differs from the one-thread run";
    }
  }
}

} // namespace

TEST(Threads, WorkAskingForEveryCoreStaysWithinTheLimit)
{
  // The CLI sets the limit from --threads: work that asks for every core (0), as the validation and
  // the self-intersection test do, then runs on no more threads than that.
  auto threadsUsed = [](unsigned int asked)
  {
    std::mutex lock;
    std::set<std::thread::id> used;
    parallelFor(64, asked,
                [&](std::size_t)
                {
                  std::this_thread::sleep_for(std::chrono::milliseconds(2));
                  const std::lock_guard<std::mutex> guard(lock);
                  used.insert(std::this_thread::get_id());
                });
    return used.size();
  };
  everyCoreLimit() = 1;
  EXPECT_EQ(threadCount(0), 1u);
  EXPECT_EQ(threadsUsed(0), 1u);
  EXPECT_EQ(threadCount(3), 3u); // an explicit count is kept
  everyCoreLimit() = 0;
  EXPECT_EQ(threadCount(0), std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_GE(threadsUsed(2), 1u);
  EXPECT_LE(threadsUsed(2), 2u);
}

} // namespace slicemesh::testing

// The same contour stack gives the same mesh, bit for bit, whatever the heap looks like. The tiling
// once took CGAL's edge order, which follows face addresses, so the flips and Steiner points (and
// the validity of a random mask's mesh) changed from run to run.
#include "ContourStacks.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

using namespace slicemesh;
using slicemesh::testing::randomShiftedStar;

namespace
{

/** Stars crossing each other between thick slices, with holes: many flips and refinement rounds. */
ContourStack crossingStars(int seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-1.5, 1.5);
  std::uniform_int_distribution<int> points(12, 60);
  ContourStack stack;
  stack.sliceSpacing = 3.0;
  for (int k = 0; k < 6; ++k)
  {
    Slice slice{ 3.0 * k, {} };
    slice.contours.push_back(randomShiftedStar(rng, shift, points, 10.0, false));
    if (k > 0 && k < 5)
      slice.contours.push_back(randomShiftedStar(rng, shift, points, 3.0, true));
    stack.slices.push_back(slice);
  }
  return stack;
}

bool identical(const TriangleMesh& a, const TriangleMesh& b)
{
  if (a.points.size() != b.points.size() || a.triangles.size() != b.triangles.size())
    return false;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (a.points[i].x != b.points[i].x || a.points[i].y != b.points[i].y || a.points[i].z != b.points[i].z)
      return false;
  for (std::size_t t = 0; t < a.triangles.size(); ++t)
    if (a.triangles[t] != b.triangles[t])
      return false;
  return true;
}

} // namespace

TEST(Determinism, SameStackGivesTheSameMeshWhateverTheHeapLayout)
{
  for (int seed = 1; seed <= 6; ++seed)
  {
    const ContourStack stack = crossingStars(seed);
    const TriangleMesh first = reconstructSurface(stack);
    // Blocks of assorted sizes kept alive between the runs move where CGAL's faces land.
    std::vector<std::unique_ptr<char[]>> ballast;
    for (int run = 1; run <= 4; ++run)
    {
      for (int j = 0; j < 200 * run; ++j)
        ballast.emplace_back(new char[24 + 40 * (j % 17)]);
      const TriangleMesh again = reconstructSurface(stack);
      EXPECT_TRUE(identical(first, again)) << "seed " << seed << ", run " << run << ": " << first.points.size()
                                           << " then " << again.points.size() << " points";
    }
  }
}

TEST(Determinism, SlabsTiledSideBySideGiveTheSameMeshAsOneAfterTheOther)
{
  // Slabs go in batches of twice the threads: 3 threads make batches of 6 over the 7 slabs of a
  // 6-slice stack, so a batch boundary falls inside the stack.
  for (int seed = 1; seed <= 6; ++seed)
  {
    const ContourStack stack = crossingStars(seed);
    ReconstructionOptions one;
    one.threads = 1;
    ReconstructionStatistics sequential, parallel;
    const TriangleMesh first = reconstructSurface(stack, one, &sequential);
    for (unsigned int threads : { 2u, 3u, 8u })
    {
      ReconstructionOptions several = one;
      several.threads = threads;
      const TriangleMesh again = reconstructSurface(stack, several, &parallel);
      EXPECT_TRUE(identical(first, again)) << "seed " << seed << ", " << threads << " threads";
      EXPECT_EQ(parallel.steinerPoints, sequential.steinerPoints);
      EXPECT_EQ(parallel.tilingTriangles + parallel.wallTriangles + parallel.capTriangles,
                sequential.tilingTriangles + sequential.wallTriangles + sequential.capTriangles);
      EXPECT_EQ(parallel.slabs, sequential.slabs);
    }
  }
}

// contourVolumes: each contour's share of a stack's volume; on a mask's pixels, its own voxels.
#include "ContourStacks.h"
#include "Measures/ContourVolumes.h"
#include "Measures/StackVolume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace slicemesh::testing
{
namespace
{

double sum(const std::vector<ContourVolume>& shares)
{
  return std::accumulate(shares.begin(), shares.end(), 0.0,
                         [](double total, const ContourVolume& share) { return total + share.volume; });
}

/** The contour traced around a block of pixels (columns i0..i1, rows j0..j1) of a mask whose pixels
 *  are `sx` by `sy`: through the midpoints between the block's pixel centres and the others'. */
Polygon2 tracedBlock(double i0, double j0, double i1, double j1, double sx, double sy)
{
  const double x0 = i0 - 0.5, x1 = i1 + 0.5, y0 = j0 - 0.5, y1 = j1 + 0.5;
  Polygon2 block{ { x0, j0 }, { i0, y0 }, { i1, y0 }, { x1, j0 }, { x1, j1 }, { i1, y1 }, { i0, y1 }, { x0, j1 } };
  for (Point2& p : block)
    p = { p.x * sx, p.y * sy };
  return block;
}

TEST(ContourVolumes, OnAMasksPixelsEachContourCountsItsVoxels)
{
  const double sx = 0.5, sy = 0.8;
  ContourStack stack;
  stack.sliceSpacing = 2.0;
  // A 5 x 5 block with its centre pixel unset (a hole, traced as a diamond around it), and a single
  // pixel traced as a diamond of half its area.
  Polygon2 hole = tracedBlock(2, 2, 2, 2, sx, sy);
  std::reverse(hole.begin(), hole.end());
  stack.slices.push_back({ 0.0, { tracedBlock(0, 0, 4, 4, sx, sy), hole, tracedBlock(8, 1, 8, 1, sx, sy) } });
  const std::vector<ContourVolume> shares = contourVolumes(stack, { sx, sy });
  ASSERT_EQ(shares.size(), 3u);
  const double voxel = sx * sy * 2.0;
  EXPECT_NEAR(shares[0].volume, 25 * voxel, 1e-12);
  EXPECT_NEAR(shares[1].volume, -1 * voxel, 1e-12);
  EXPECT_NEAR(shares[2].volume, 1 * voxel, 1e-12);
  EXPECT_EQ(shares[2].point.z, 0.0);
  // By area, the single pixel's diamond is half a voxel.
  const std::vector<ContourVolume> byArea = contourVolumes(stack);
  EXPECT_NEAR(byArea[2].volume, 0.5 * voxel, 1e-12);
}

TEST(ContourVolumes, ByAreaTheSharesAddUpToThePrismVolume)
{
  ContourStack stack;
  for (double z : { 0.0, 1.0, 4.0 })
    stack.slices.push_back({ z, { circle(0.0, 0.0, 10.0, 64), circle(0.0, 0.0, 4.0, 32, true), rectangle(20.0, 0.0, 23.0, 2.0) } });
  const std::vector<ContourVolume> shares = contourVolumes(stack);
  ASSERT_EQ(shares.size(), 9u);
  EXPECT_NEAR(sum(shares), prismVolume(stack), 1e-9 * prismVolume(stack));
  for (const ContourVolume& share : shares)
    EXPECT_TRUE(share.point.z == 0.0 || share.point.z == 1.0 || share.point.z == 4.0);
}

} // namespace
} // namespace slicemesh::testing

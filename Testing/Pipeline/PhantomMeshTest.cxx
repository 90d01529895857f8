// End to end on analytic phantoms: rasterized label maps -> contours -> surface in physical space,
// measured against the exact surfaces. Tolerances follow from the input: a binary mask contoured at
// its 0.5 level places every contour vertex within half a voxel of the true surface along the grid
// axes, and caps half a slice beyond the last contour.
#include "Box.h"
#include "CappedCylinder.h"
#include "Ellipsoid.h"
#include "PhantomMeshing.h"
#include "Sphere.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** Checks validity, volume, distance and bounding box; returns the result for extra checks.
 *  The mask itself misses the analytic volume (a box whose faces fall near voxel centres gains or
 *  loses a whole layer), so the volume is held to the mask's voxel volume within volumeTolerance,
 *  and to the analytic volume within the mask's own error plus volumeTolerance. */
PhantomMeshResult expectFaithful(const Phantom& phantom, const PhantomTestGrid& grid, double volumeTolerance = 0.04)
{
  const PhantomMeshResult r = meshPhantom(phantom, grid.spacing, grid.direction);
  const double halfDiagonal =
    0.5 * std::sqrt(grid.spacing[0] * grid.spacing[0] + grid.spacing[1] * grid.spacing[1] + grid.spacing[2] * grid.spacing[2]);
  std::printf("%-14s %s; volume %+.2f%% (voxels %+.2f%%), distance mean %.3f max %.3f mm, min angle %.1f, <30deg %.1f%%\n",
              grid.name, r.validation.summary().c_str(), 100.0 * (r.validation.volume / phantom.volume() - 1.0),
              100.0 * (r.voxelVolume / phantom.volume() - 1.0), r.meanDistance, r.maxDistance,
              r.validation.minAngleDegrees, 100.0 * r.validation.fractionAnglesBelow30);
  EXPECT_TRUE(r.validation.valid()) << r.validation.summary();
  EXPECT_EQ(r.validation.components, 1u);
  EXPECT_EQ(r.validation.eulerCharacteristic, 2);
  EXPECT_NEAR(r.validation.volume, r.voxelVolume, volumeTolerance * r.voxelVolume);
  EXPECT_NEAR(r.validation.volume, phantom.volume(),
              std::abs(r.voxelVolume - phantom.volume()) + volumeTolerance * phantom.volume());
  // Every vertex within half a voxel diagonal of the exact surface; on average far closer.
  EXPECT_LE(r.maxDistance, halfDiagonal);
  EXPECT_LE(r.meanDistance, 0.4 * halfDiagonal);
  // The bounding box where the shape's is, within half a voxel diagonal.
  const Bounds b = phantom.bounds();
  EXPECT_NEAR(r.lower.x, b.lower.x(), halfDiagonal);
  EXPECT_NEAR(r.lower.y, b.lower.y(), halfDiagonal);
  EXPECT_NEAR(r.lower.z, b.lower.z(), halfDiagonal);
  EXPECT_NEAR(r.upper.x, b.upper.x(), halfDiagonal);
  EXPECT_NEAR(r.upper.y, b.upper.y(), halfDiagonal);
  EXPECT_NEAR(r.upper.z, b.upper.z(), halfDiagonal);
  return r;
}

} // namespace

TEST(PhantomMesh, Sphere)
{
  const Sphere sphere({ 10.0, -20.0, 35.0 }, 12.0);
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFaithful(sphere, grid);
}

TEST(PhantomMesh, RotatedEllipsoid)
{
  const Ellipsoid ellipsoid({ -5.0, 8.0, 12.0 }, { 14.0, 9.0, 11.0 }, rotation({ 0.3, 1.0, 0.2 }, 0.7));
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFaithful(ellipsoid, grid);
}

TEST(PhantomMesh, StraightCylinder)
{
  // Sizes off the voxel grid, so the mask is not biased by faces falling on voxel centres.
  const CappedCylinder cylinder({ 0.3, -0.2, 0.1 }, { 0.0, 0.0, 1.0 }, 9.3, 15.2);
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFaithful(cylinder, grid);
}

TEST(PhantomMesh, Box)
{
  const Box box({ 3.1, 4.2, 5.3 }, { 10.3, 7.4, 12.2 });
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFaithful(box, grid);
}

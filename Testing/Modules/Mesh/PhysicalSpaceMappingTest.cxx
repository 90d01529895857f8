// mapToPhysicalSpace: origin + direction * (x, y, z), LPS or RAS, winding kept outward.
#include "MeshWriter.h"
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slicemesh
{
namespace
{

SliceFrame frameWith(std::array<double, 3> origin, std::array<std::array<double, 3>, 3> direction)
{
  SliceFrame frame;
  frame.origin = origin;
  frame.direction = direction;
  return frame;
}

TEST(PhysicalSpaceMapping, IdentityDirectionTranslatesByOrigin)
{
  const TriangleMesh stack = testing::box(2, 3, 4);
  const SliceFrame frame = frameWith({ 10, 20, 30 }, { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } });
  const TriangleMesh lps = mapToPhysicalSpace(stack, frame, CoordinateSystem::LPS);
  ASSERT_EQ(lps.points.size(), stack.points.size());
  EXPECT_DOUBLE_EQ(lps.points[6].x, 12.0);
  EXPECT_DOUBLE_EQ(lps.points[6].y, 23.0);
  EXPECT_DOUBLE_EQ(lps.points[6].z, 34.0);
  EXPECT_EQ(lps.triangles, stack.triangles);
}

TEST(PhysicalSpaceMapping, RASNegatesXAndYOnly)
{
  const TriangleMesh stack = testing::box(2, 3, 4);
  const SliceFrame frame = frameWith({ 10, 20, 30 }, { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } });
  const TriangleMesh lps = mapToPhysicalSpace(stack, frame, CoordinateSystem::LPS);
  const TriangleMesh ras = mapToPhysicalSpace(stack, frame, CoordinateSystem::RAS);
  for (std::size_t i = 0; i < lps.points.size(); ++i)
  {
    EXPECT_DOUBLE_EQ(ras.points[i].x, -lps.points[i].x);
    EXPECT_DOUBLE_EQ(ras.points[i].y, -lps.points[i].y);
    EXPECT_DOUBLE_EQ(ras.points[i].z, lps.points[i].z);
  }
  // LPS -> RAS is a rotation: the winding stays, the volume stays positive.
  EXPECT_EQ(ras.triangles, stack.triangles);
  EXPECT_NEAR(testing::signedVolume(ras), 24.0, 1e-9);
}

TEST(PhysicalSpaceMapping, ObliqueDirectionUsesColumnsAsAxes)
{
  // Rotation by 30 degrees about z; column j is the physical direction of stack axis j.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const SliceFrame frame = frameWith({ 1, 2, 3 }, { { { c, -s, 0 }, { s, c, 0 }, { 0, 0, 1 } } });
  TriangleMesh stack = testing::box(2, 3, 4);
  const TriangleMesh lps = mapToPhysicalSpace(stack, frame, CoordinateSystem::LPS);
  // stack point 1 is (2, 0, 0): along the first column.
  EXPECT_NEAR(lps.points[1].x, 1 + 2 * c, 1e-12);
  EXPECT_NEAR(lps.points[1].y, 2 + 2 * s, 1e-12);
  EXPECT_NEAR(lps.points[1].z, 3, 1e-12);
  EXPECT_NEAR(testing::signedVolume(lps), 24.0, 1e-9);
}

TEST(PhysicalSpaceMapping, MirroredDirectionFlipsWindingSoVolumeStaysPositive)
{
  const TriangleMesh stack = testing::box(2, 3, 4);
  // Determinant -1: the third axis points the other way (a common NIfTI/DICOM situation).
  const SliceFrame frame = frameWith({ 0, 0, 0 }, { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, -1 } } });
  for (CoordinateSystem system : { CoordinateSystem::LPS, CoordinateSystem::RAS })
  {
    const TriangleMesh mapped = mapToPhysicalSpace(stack, frame, system);
    EXPECT_NEAR(testing::signedVolume(mapped), 24.0, 1e-9);
    EXPECT_NE(mapped.triangles, stack.triangles);
    EXPECT_DOUBLE_EQ(mapped.points[6].z, -4.0);
  }
}

} // namespace
} // namespace slicemesh

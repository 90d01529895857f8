// Triangle quality measures: angles, aspect ratios, genus.
#include "Measures/MeshQuality.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slicemesh;

TEST(MeshQuality, EquilateralRightAndSliverTriangles)
{
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, std::sqrt(3.0) / 2, 0 }, // equilateral
                  { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 },                      // right isosceles
                  { 0, 0, 2 }, { 10, 0, 2 }, { 5, 0.5, 2 } };                // sliver
  mesh.triangles = { { 0, 1, 2 } };
  MeshQuality q = measureMeshQuality(mesh);
  EXPECT_NEAR(q.minAngleDegrees, 60.0, 1e-9);
  EXPECT_NEAR(q.maxAngleDegrees, 60.0, 1e-9);
  EXPECT_NEAR(q.meanAspectRatio, 1.0, 1e-12);
  EXPECT_EQ(q.fractionBelow30, 0.0);

  mesh.triangles = { { 0, 1, 2 }, { 3, 4, 5 }, { 6, 7, 8 } };
  q = measureMeshQuality(mesh);
  EXPECT_EQ(q.triangles, 3u);
  EXPECT_NEAR(q.minAngleDegrees, std::atan(0.1) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(q.maxAngleDegrees, 180.0 - 2.0 * std::atan(0.1) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(q.fractionBelow30, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(q.fractionBelow10, 1.0 / 3.0, 1e-12);
  // Right isosceles: R = sqrt2/2, r = (2 - sqrt2)/2: R / 2r = 1 / (2 (sqrt2 - 1)) = 1.2071.
  EXPECT_NEAR(q.medianAspectRatio, 1.0 / (2.0 * (std::sqrt(2.0) - 1.0)), 1e-9);
  EXPECT_GT(q.maxAspectRatio, 5.0);
  const std::vector<double> angles = triangleMinAngles(mesh);
  ASSERT_EQ(angles.size(), 3u);
  EXPECT_NEAR(angles[1], 45.0, 1e-9);

  // Angles of 30, 30 and 120 degrees exactly (half-voxel coordinates): none under 30.
  mesh.points.push_back({ 10, 20, 30 });
  mesh.points.push_back({ 11, 20.5, 30.5 });
  mesh.points.push_back({ 10.5, 20.5, 30 });
  mesh.triangles = { { 9, 10, 11 } };
  q = measureMeshQuality(mesh);
  EXPECT_NEAR(q.minAngleDegrees, 30.0, 1e-12);
  EXPECT_NEAR(q.maxAngleDegrees, 120.0, 1e-12);
  EXPECT_EQ(q.fractionBelow30, 0.0);

  // Degenerate triangle: angle 0, aspect ratio infinite.
  mesh.triangles = { { 6, 7, 6 } };
  q = measureMeshQuality(mesh);
  EXPECT_EQ(q.minAngleDegrees, 0.0);
  EXPECT_TRUE(std::isinf(q.maxAspectRatio));
}

TEST(MeshQuality, GenusFromEulerCharacteristic)
{
  MeshValidation v;
  v.triangles = 100;
  v.components = 1;
  v.eulerCharacteristic = 2;
  EXPECT_EQ(genusOf(v), 0);
  v.eulerCharacteristic = 0; // a torus
  EXPECT_EQ(genusOf(v), 1);
  v.components = 2;
  v.eulerCharacteristic = 2; // a sphere and a torus
  EXPECT_EQ(genusOf(v), 1);
  v.boundaryEdges = 3; // open: undefined
  EXPECT_EQ(genusOf(v), -1);
}

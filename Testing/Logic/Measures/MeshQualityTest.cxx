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

TEST(MeshQuality, TheSameOnAnyNumberOfThreads)
{
  // A grid of 300 x 300 squares, each cut into two triangles, the points jittered so that every
  // triangle differs: 180,000 triangles, many ranges of the measure's work.
  TriangleMesh mesh;
  const int n = 300;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.points.push_back({ i + 0.3 * std::sin(7.0 * i + 3.0 * j), j + 0.3 * std::cos(5.0 * i - 11.0 * j),
                              0.2 * std::sin(0.1 * i * j) });
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.triangles.push_back({ a, b, d });
      mesh.triangles.push_back({ a, d, c });
    }
  const MeshQuality one = measureMeshQuality(mesh, 1);
  EXPECT_EQ(one.triangles, 180000u);
  EXPECT_GT(one.fractionBelow30, 0.0);
  EXPECT_LT(one.fractionBelow30, 1.0);
  EXPECT_GT(one.maxAspectRatio, one.p95AspectRatio);
  EXPECT_GT(one.p95AspectRatio, one.medianAspectRatio);
  for (unsigned int threads : { 2u, 8u })
  {
    const MeshQuality many = measureMeshQuality(mesh, threads);
    EXPECT_EQ(many.minAngleDegrees, one.minAngleDegrees) << threads;
    EXPECT_EQ(many.maxAngleDegrees, one.maxAngleDegrees) << threads;
    EXPECT_EQ(many.fractionBelow30, one.fractionBelow30) << threads;
    EXPECT_EQ(many.fractionBelow10, one.fractionBelow10) << threads;
    EXPECT_EQ(many.meanAspectRatio, one.meanAspectRatio) << threads;
    EXPECT_EQ(many.medianAspectRatio, one.medianAspectRatio) << threads;
    EXPECT_EQ(many.p95AspectRatio, one.p95AspectRatio) << threads;
    EXPECT_EQ(many.maxAspectRatio, one.maxAspectRatio) << threads;
  }
}

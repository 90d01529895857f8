#include "ContourStacks.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

MeshValidation expectValid(const TriangleMesh& mesh)
{
  const MeshValidation v = validateMesh(mesh);
  EXPECT_TRUE(v.closed()) << v.summary();
  EXPECT_TRUE(v.manifold()) << v.summary() << " non-manifold edges " << v.nonManifoldEdges << " vertices "
                            << v.nonManifoldVertices;
  EXPECT_EQ(v.inconsistentEdges, 0u);
  EXPECT_EQ(v.degenerateTriangles, 0u);
  EXPECT_TRUE(v.selfIntersectionChecked);
  EXPECT_EQ(v.selfIntersections, 0u) << v.summary();
  EXPECT_GT(v.volume, 0.0);
  return v;
}

double minAngleDegrees(const Point3& a, const Point3& b, const Point3& c)
{
  auto angle = [](const Point3& o, const Point3& p, const Point3& q) {
    const double ux = p.x - o.x, uy = p.y - o.y, uz = p.z - o.z, vx = q.x - o.x, vy = q.y - o.y, vz = q.z - o.z;
    const double dot = ux * vx + uy * vy + uz * vz;
    return std::acos(dot / std::sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz))) * 180.0 / M_PI;
  };
  return std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) });
}

} // namespace

TEST(SurfaceReconstruction, SphereFromCircles)
{
  const double r = 20.0;
  const ContourStack stack = sliceStack(-19.0, 19.0, 2.0, [&](double z) {
    return std::vector<Polygon2>{ circle(0, 0, std::sqrt(r * r - z * z), 90) };
  });
  ReconstructionStatistics statistics;
  const TriangleMesh mesh = reconstructSurface(stack, {}, &statistics);
  const MeshValidation v = expectValid(mesh);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.eulerCharacteristic, 2);
  const double exact = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_NEAR(v.volume, exact, 0.03 * exact);
}

TEST(SurfaceReconstruction, StraightCylinderGivesVerticalWalls)
{
  const ContourStack stack = sliceStack(0.0, 30.0, 3.0, [](double) {
    return std::vector<Polygon2>{ circle(5, -3, 10.0, 64) };
  });
  ReconstructionStatistics statistics;
  const TriangleMesh mesh = reconstructSurface(stack, {}, &statistics);
  const MeshValidation v = expectValid(mesh);
  EXPECT_EQ(statistics.tilingTriangles, 0u);
  EXPECT_GT(statistics.wallTriangles, 0u);
  // The prism over the 64-gon, 30 mm between the end slices, plus a dome at each end rising
  // r = 1.5 mm (half a slice) on a quarter circle: each dome lacks about perimeter * r^2 (1 - pi/4)
  // of the 1.5 mm prism the voxels would fill.
  const double area = 0.5 * 64 * 100.0 * std::sin(2 * M_PI / 64);
  const double perimeter = 64 * 2 * 10.0 * std::sin(M_PI / 64);
  const double domeDeficit = perimeter * 1.5 * 1.5 * (1.0 - M_PI / 4.0);
  EXPECT_NEAR(v.volume, area * 33.0 - 2.0 * domeDeficit, 0.15 * 2.0 * domeDeficit);
  // Wall triangles (normals horizontal) are cut into rows close to the edge length: well shaped.
  double smallestWallAngle = 180.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    // A wall triangle has a vertical edge: two corners above the same contour vertex.
    auto above = [](const Point3& p, const Point3& q) { return p.x == q.x && p.y == q.y; };
    if (!(above(a, b) || above(b, c) || above(c, a)))
      continue;
    smallestWallAngle = std::min(smallestWallAngle, minAngleDegrees(a, b, c));
  }
  EXPECT_GT(smallestWallAngle, 25.0);
}

TEST(SurfaceReconstruction, ShiftedAndRotatedCirclesCross)
{
  // Each slice's circle is shifted and its points rotated: contours of adjacent slices cross.
  const ContourStack stack = sliceStack(0.0, 20.0, 1.0, [](double z) {
    return std::vector<Polygon2>{ circle(0.3 * z, 0.0, 8.0 + 0.1 * z, 40, false, 0.05 * z) };
  });
  ReconstructionStatistics statistics;
  const TriangleMesh mesh = reconstructSurface(stack, {}, &statistics);
  expectValid(mesh);
  EXPECT_GT(statistics.crossingPoints, 0u);
}

TEST(SurfaceReconstruction, AnnulusStackKeepsItsHole)
{
  const ContourStack stack = sliceStack(0.0, 10.0, 1.0, [](double z) {
    return std::vector<Polygon2>{ circle(0, 0, 10.0, 60), circle(0.1 * z, 0, 4.0, 30, true) };
  });
  const TriangleMesh mesh = reconstructSurface(stack);
  const MeshValidation v = expectValid(mesh);
  EXPECT_EQ(v.eulerCharacteristic, 0) << "a solid torus has genus 1";
}

TEST(SurfaceReconstruction, TwoContoursMergeIntoOne)
{
  const ContourStack stack = sliceStack(0.0, 6.0, 1.0, [](double z) {
    if (z < 2.5)
      return std::vector<Polygon2>{ circle(-5, 0, 4.0, 40), circle(5, 0, 4.0, 40) };
    return std::vector<Polygon2>{ circle(0, 0, 10.0, 80) };
  });
  const TriangleMesh mesh = reconstructSurface(stack);
  const MeshValidation v = expectValid(mesh);
  EXPECT_EQ(v.components, 1u);
  EXPECT_EQ(v.eulerCharacteristic, 2);
}

TEST(SurfaceReconstruction, VoxelStaircase)
{
  // Rectangles that grow by whole voxels: long coincident runs with different vertex sets.
  const ContourStack stack = sliceStack(0.0, 8.0, 1.0, [](double z) {
    const double grow = std::floor(z / 2.0);
    Polygon2 p;
    for (double x = 0; x < 5 + grow; x += 1.0)
      p.push_back({ x, 0 });
    for (double y = 0; y < 4; y += 1.0)
      p.push_back({ 5 + grow, y });
    for (double x = 5 + grow; x > 0; x -= 1.0)
      p.push_back({ x, 4 });
    for (double y = 4; y > 0; y -= 1.0)
      p.push_back({ 0, y });
    return std::vector<Polygon2>{ p };
  });
  ReconstructionStatistics statistics;
  const TriangleMesh mesh = reconstructSurface(stack, {}, &statistics);
  const MeshValidation v = expectValid(mesh);
  EXPECT_EQ(v.eulerCharacteristic, 2);
  EXPECT_GT(v.minAngleDegrees, 10.0);
}

TEST(SurfaceReconstruction, CapsAtTheSliceItself)
{
  const ContourStack stack = sliceStack(0.0, 4.0, 1.0, [](double) {
    return std::vector<Polygon2>{ rectangle(0, 0, 3, 2) };
  });
  ReconstructionOptions options;
  options.capPlacement = CapPlacement::AtSlice;
  const MeshValidation v = expectValid(reconstructSurface(stack, options));
  EXPECT_NEAR(v.volume, 3 * 2 * 4.0, 1e-9);
}

TEST(SurfaceReconstruction, SingleSliceGetsAThickness)
{
  ContourStack stack;
  stack.sliceSpacing = 2.0;
  stack.slices.push_back({ 1.0, { rectangle(0, 0, 3, 2) } });
  for (CapPlacement placement : { CapPlacement::HalfSliceBeyond, CapPlacement::AtSlice })
  {
    ReconstructionOptions options;
    options.capPlacement = placement;
    const MeshValidation v = expectValid(reconstructSurface(stack, options));
    // Two domes of 1 mm over the 3 x 2 mm rectangle: more than the bare lens of two pyramids-like
    // halves, less than the 2 mm slab the voxels fill.
    EXPECT_GT(v.volume, 3 * 2 * 2.0 * 0.3);
    EXPECT_LT(v.volume, 3 * 2 * 2.0);
  }
}

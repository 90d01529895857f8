// The remesh's projection grid (ClosestPointGrid) finds the closest point CGAL's AABB tree finds: on a
// bumpy closed surface, from points near it and far from it, with hints on the surface near and far
// from the answer (a far one goes to the tree), and from points right on edges and corners, where
// several triangles are equally close and either may give the point.
#include "Measures/ClosestPointGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace slicemesh;

namespace
{

/** A sphere of latitude-longitude rings with a bumpy radius: triangles of many sizes and slopes. */
TriangleMesh bumpySphere(int rings, int sectors)
{
  TriangleMesh mesh;
  auto radius = [](double polar, double azimuth) { return 20.0 + 1.5 * std::sin(5.0 * polar) * std::cos(3.0 * azimuth); };
  mesh.points.push_back({ 0.0, 0.0, -radius(0.0, 0.0) });
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s)
    {
      const double polar = M_PI * r / rings, azimuth = 2.0 * M_PI * s / sectors, rho = radius(polar, azimuth);
      mesh.points.push_back({ rho * std::sin(polar) * std::cos(azimuth), rho * std::sin(polar) * std::sin(azimuth),
                              -rho * std::cos(polar) });
    }
  mesh.points.push_back({ 0.0, 0.0, radius(M_PI, 0.0) });
  const auto top = static_cast<std::int32_t>(mesh.points.size() - 1);
  auto at = [sectors](int r, int s) { return static_cast<std::int32_t>(1 + (r - 1) * sectors + (s % sectors)); };
  for (int s = 0; s < sectors; ++s)
  {
    mesh.triangles.push_back({ 0, at(1, s + 1), at(1, s) });
    mesh.triangles.push_back({ top, at(rings - 1, s), at(rings - 1, s + 1) });
    for (int r = 1; r + 1 < rings; ++r)
    {
      mesh.triangles.push_back({ at(r, s), at(r, s + 1), at(r + 1, s + 1) });
      mesh.triangles.push_back({ at(r, s), at(r + 1, s + 1), at(r + 1, s) });
    }
  }
  return mesh;
}

} // namespace

TEST(ClosestPointGrid, FindsThePointTheTreeFinds)
{
  const TriangleMesh mesh = bumpySphere(40, 64);
  TriangleMeshTree tree;
  insertTriangles(tree, mesh);
  tree.build();
  const ClosestPointGrid grid(mesh);
  EXPECT_GT(grid.cellSize(), 0.0);

  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> anyPoint(0, mesh.points.size() - 1);
  std::size_t queries = 0, differingPoints = 0;
  double largestDistanceDifference = 0.0;
  auto compare = [&](const CgalKernel::Point_3& query, const CgalKernel::Point_3& hint)
  {
    ++queries;
    const CgalKernel::Point_3 expected = tree.closest_point(query);
    const CgalKernel::Point_3 found = grid.closestPoint(query, hint);
    differingPoints += found != expected;
    largestDistanceDifference =
      std::max(largestDistanceDifference, std::abs(std::sqrt(CGAL::squared_distance(query, found)) -
                                                   std::sqrt(CGAL::squared_distance(query, expected))));
    // Without a hint: the tree's own answer.
    EXPECT_EQ(grid.closestPoint(query), expected);
  };
  for (int n = 0; n < 4000; ++n)
  {
    // A vertex of the mesh (on the surface: a valid hint), and a point moved off it by up to 0.05
    // to 5 mm: the remesh's queries are a fraction of an edge from their hint.
    const Point3& v = mesh.points[anyPoint(random)];
    const double reach = n % 4 == 0 ? 5.0 : n % 4 == 1 ? 1.0 : n % 4 == 2 ? 0.3 : 0.05;
    const CgalKernel::Point_3 query(v.x + reach * unit(random), v.y + reach * unit(random), v.z + reach * unit(random));
    compare(query, CgalKernel::Point_3(v.x, v.y, v.z));
    // A hint anywhere on the surface, most often far from the answer.
    const Point3& far = mesh.points[anyPoint(random)];
    compare(query, CgalKernel::Point_3(far.x, far.y, far.z));
  }
  // Queries right on vertices and on the middle of edges: several triangles give the same distance.
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 7)
  {
    const Point3& a = mesh.points[mesh.triangles[t][0]];
    const Point3& b = mesh.points[mesh.triangles[t][1]];
    compare(CgalKernel::Point_3(a.x, a.y, a.z), CgalKernel::Point_3(b.x, b.y, b.z));
    compare(CgalKernel::Point_3(0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)), CgalKernel::Point_3(a.x, a.y, a.z));
  }
  std::printf("%zu queries: %zu points differ from the tree's in their bits, distances by at most %.3g mm\n", queries,
              differingPoints, largestDistanceDifference);
  EXPECT_GT(queries, 8000u);
  // Equally close points may differ where two triangles meet; the distance may not.
  EXPECT_LE(largestDistanceDifference, 1e-12);
  EXPECT_LE(differingPoints, queries / 100);
}

TEST(ClosestPointGrid, ALongTriangleAmongSmallOnesIsFound)
{
  // One long thin triangle across a field of small ones: the grid's cells follow the small ones,
  // and the long one, in many cells, is still found from anywhere along it.
  TriangleMesh mesh;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j)
    {
      const auto base = static_cast<std::int32_t>(mesh.points.size());
      mesh.points.push_back({ 0.5 * i, 0.5 * j, 0.0 });
      mesh.points.push_back({ 0.5 * i + 0.4, 0.5 * j, 0.0 });
      mesh.points.push_back({ 0.5 * i, 0.5 * j + 0.4, 0.0 });
      mesh.triangles.push_back({ base, base + 1, base + 2 });
    }
  const auto base = static_cast<std::int32_t>(mesh.points.size());
  mesh.points.push_back({ -5.0, 10.0, 1.0 });
  mesh.points.push_back({ 40.0, 10.0, 1.0 });
  mesh.points.push_back({ 40.0, 10.5, 1.0 });
  mesh.triangles.push_back({ base, base + 1, base + 2 });
  TriangleMeshTree tree;
  insertTriangles(tree, mesh);
  tree.build();
  const ClosestPointGrid grid(mesh);
  for (double x = -4.0; x < 39.0; x += 0.37)
  {
    const CgalKernel::Point_3 query(x, 10.2, 1.2);
    // The hint a corner of the small triangles below (1.2 mm down), farther than the long one above
    // (0.2 mm): a few cells around the query are searched.
    const CgalKernel::Point_3 hint(0.5 * std::round(std::clamp(x, 0.0, 24.5) / 0.5), 10.0, 0.0);
    EXPECT_EQ(grid.closestPoint(query, hint), tree.closest_point(query)) << x;
  }
}

// The remesh's projection grid (ClosestPointGrid) finds the closest point CGAL's AABB tree finds: on a
// bumpy closed surface, from points near it and far from it, with hints on the surface near and far
// from the answer (a far one goes to the tree), and from points right on edges and corners, where
// several triangles are equally close and either may give the point.
#include "Measures/ClosestPointGrid.h"

#include "ClosestPointCases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace slicemesh;

using slicemesh::testing::bumpySphere;
using slicemesh::testing::forEachClosestPointQuery;

TEST(ClosestPointGrid, FindsThePointTheTreeFinds)
{
  const TriangleMesh mesh = bumpySphere(40, 64);
  TriangleMeshTree tree;
  insertTriangles(tree, mesh);
  tree.build();
  const ClosestPointGrid grid(mesh);
  EXPECT_GT(grid.cellSize(), 0.0);

  std::size_t queries = 0, differingPoints = 0;
  double largestDistanceDifference = 0.0;
  auto check = [&](const CgalKernel::Point_3& query, const CgalKernel::Point_3& found)
  {
    ++queries;
    const CgalKernel::Point_3 expected = tree.closest_point(query);
    differingPoints += found != expected;
    largestDistanceDifference =
      std::max(largestDistanceDifference, std::abs(std::sqrt(CGAL::squared_distance(query, found)) -
                                                   std::sqrt(CGAL::squared_distance(query, expected))));
  };
  // With the hint, and without one (the shells around the query's cell alone).
  auto compare = [&](const CgalKernel::Point_3& query, const CgalKernel::Point_3& hint)
  {
    check(query, grid.closestPoint(query, hint));
    check(query, grid.closestPoint(query));
  };
  forEachClosestPointQuery(mesh, compare);
  std::printf("%zu queries: %zu points differ from the tree's in their bits, distances by at most %.3g mm\n", queries,
              differingPoints, largestDistanceDifference);
  EXPECT_GT(queries, 16000u);
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

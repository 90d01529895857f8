// The remesh's closest-point search (ClosestPointSearch) returns what CGAL's tree.closest_point does,
// bit for bit: on a bumpy closed surface, from points near it and far from it, with hints on the
// surface near and far from the answer, and from points right on edges and corners, where several
// triangles are equally close.
#include "Measures/TriangleMeshTree.h"

#include "ClosestPointCases.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slicemesh;

using slicemesh::testing::bumpySphere;
using slicemesh::testing::forEachClosestPointQuery;

TEST(TriangleMeshTree, ClosestPointSearchFindsCgalsPointBitForBit)
{
  const TriangleMesh mesh = bumpySphere(40, 64);
  TriangleMeshTree tree;
  insertTriangles(tree, mesh);
  tree.do_not_accelerate_distance_queries();
  tree.build();

  std::size_t queries = 0, differing = 0;
  auto compare = [&](const CgalKernel::Point_3& query, const CgalKernel::Point_3& hint)
  {
    ++queries;
    differing += closestPoint(tree, query, hint) != tree.closest_point(query, hint);
  };
  forEachClosestPointQuery(mesh, compare);
  EXPECT_GT(queries, 8000u);
  EXPECT_EQ(differing, 0u);
}

// EdgeUses: every triangle's use of every edge, filed under the edge's lower vertex in order.
#include "Measures/EdgeUses.h"

#include <gtest/gtest.h>

using namespace slicemesh;

TEST(EdgeUses, AClosedSurfaceUsesEachEdgeOnceEachWayInOrder)
{
  // A tetrahedron, outward: each of its 6 edges is used by two triangles, in opposite directions.
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  mesh.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } };
  for (unsigned int threads : { 1u, 2u })
  {
    const EdgeUses edges(mesh, threads);
    ASSERT_EQ(edges.vertices(), 4u);
    ASSERT_EQ(edges.uses().size(), 12u);
    for (std::size_t v = 0; v < edges.vertices(); ++v)
    {
      for (std::size_t u = edges.first(v); u < edges.first(v + 1); ++u)
      {
        const EdgeUse& use = edges.uses()[u];
        EXPECT_GT(use.other, static_cast<std::int32_t>(v)) << "filed under the lower vertex";
        if (u > edges.first(v))
          EXPECT_LT(edges.uses()[u - 1], use) << "in increasing order";
        // The direction is the triangle's own.
        const Triangle& t = mesh.triangles[use.triangle];
        int at = 0;
        while (t[at] != static_cast<std::int32_t>(v))
          ++at;
        EXPECT_EQ(use.forward, t[(at + 1) % 3] == use.other);
      }
      // Two uses of each edge, one each way.
      for (std::size_t u = edges.first(v); u < edges.first(v + 1); u += 2)
      {
        EXPECT_EQ(edges.uses()[u].other, edges.uses()[u + 1].other);
        EXPECT_NE(edges.uses()[u].forward, edges.uses()[u + 1].forward);
      }
    }
    EXPECT_EQ(edges.first(3), edges.first(4)) << "the highest vertex is no edge's lower one";
    EXPECT_TRUE(edges.contains(2, 1));
    EXPECT_TRUE(edges.contains(0, 3));
  }
  mesh.triangles.pop_back(); // open: edges 0-3, 2-3 and 0-2 lose a use; none is new
  const EdgeUses open(mesh, 1);
  EXPECT_EQ(open.uses().size(), 9u);
  EXPECT_TRUE(open.contains(0, 2));
  mesh.points.push_back({ 2, 2, 2 });
  const EdgeUses apart(mesh, 1);
  EXPECT_FALSE(apart.contains(0, 4)) << "a vertex in no triangle is in no edge";
}

#include "ContourStacks.h"
#include "Correspondence/MutualIntersections.h"
#include "Core/PlanarGeometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{
bool hasVertex(const Polygon2& polygon, const Point2& p)
{
  for (const Point2& q : polygon)
    if (distance(p, q) < 1e-12)
      return true;
  return false;
}

/** A circle of 24 points whose neighbour slice is a rectangle with its left edge 0.06 from the
 *  circle's vertices at +-15 degrees, after the crossing points went into both. */
struct CircleCrossedNextToTwoVertices
{
  std::vector<Polygon2> lower{ circle(0, 0, 2, 24) };
  std::vector<Polygon2> upper{ rectangle(1.94, -1.2, 3, 1.2) };
  std::size_t crossings = insertMutualIntersections(lower, upper, 1e-9);
};
} // namespace

TEST(MutualIntersections, CrossingSquaresShareTheirCrossingPoints)
{
  std::vector<Polygon2> lower{ rectangle(0, 0, 2, 2) };
  std::vector<Polygon2> upper{ rectangle(1, 1, 3, 3) };
  EXPECT_EQ(insertMutualIntersections(lower, upper, 1e-9), 2u);
  for (const Point2& x : { Point2{ 2, 1 }, Point2{ 1, 2 } })
  {
    EXPECT_TRUE(hasVertex(lower[0], x));
    EXPECT_TRUE(hasVertex(upper[0], x));
  }
  EXPECT_EQ(lower[0].size(), 6u);
  EXPECT_EQ(upper[0].size(), 6u);
  EXPECT_DOUBLE_EQ(twiceSignedArea(lower[0]), 8.0) << "inserted points lie on the old edges";
}

TEST(MutualIntersections, CollinearRunsGetEachOthersVertices)
{
  // A staircase wall: the upper run is longer and carries vertices the lower lacks.
  std::vector<Polygon2> lower{ { { 0, 0 }, { 2, 0 }, { 2, 1 }, { 0, 1 } } };
  std::vector<Polygon2> upper{ { { 0, 0 }, { 1, 0 }, { 3, 0 }, { 3, 1 }, { 0, 1 } } };
  EXPECT_EQ(insertMutualIntersections(lower, upper, 1e-9), 0u);
  EXPECT_TRUE(hasVertex(lower[0], { 1, 0 }));
  EXPECT_TRUE(hasVertex(upper[0], { 2, 0 }));
  EXPECT_TRUE(hasVertex(upper[0], { 2, 1 }));
}

TEST(MutualIntersections, DisjointContoursAreUntouched)
{
  std::vector<Polygon2> lower{ circle(0, 0, 1, 16) };
  std::vector<Polygon2> upper{ circle(5, 0, 1, 16) };
  EXPECT_EQ(insertMutualIntersections(lower, upper, 1e-9), 0u);
  EXPECT_EQ(lower[0].size(), 16u);
  EXPECT_EQ(upper[0].size(), 16u);
}

TEST(MutualIntersections, VertexNextToACrossingIsRemoved)
{
  // The two vertices next to the crossings would end contour edges a tenth as long as the others.
  CircleCrossedNextToTwoVertices slices;
  std::vector<Polygon2>& lower = slices.lower;
  std::vector<Polygon2>& upper = slices.upper;
  EXPECT_EQ(slices.crossings, 2u);
  ASSERT_EQ(lower[0].size(), 26u);
  const Point2 nearVertex = lower[0][2];
  EXPECT_EQ(removeVerticesNearCommonOnes(upper, &lower, nullptr, 0.15, 1e-9), 0u) << "a contour keeps eight points";
  EXPECT_EQ(removeVerticesNearCommonOnes(lower, nullptr, &upper, 0.15, 1e-9), 2u);
  EXPECT_EQ(lower[0].size(), 24u);
  EXPECT_FALSE(hasVertex(lower[0], nearVertex));
  for (const Point2& crossing : upper[0])
    if (crossing.x == 1.94 && std::abs(crossing.y) < 1.0)
      EXPECT_TRUE(hasVertex(lower[0], crossing));
  // The slices still meet only at their common vertices: nothing more to insert.
  EXPECT_EQ(insertMutualIntersections(lower, upper, 1e-9), 0u);
  EXPECT_EQ(lower[0].size(), 24u);
  EXPECT_EQ(upper[0].size(), 6u);
}

TEST(MutualIntersections, VertexWhoseCornerHoldsAContourStays)
{
  // A small contour of the next slice lies whole in the corner the vertex would cut off: removing
  // the vertex would put it outside the lower contour.
  CircleCrossedNextToTwoVertices slices;
  std::vector<Polygon2>& lower = slices.lower;
  std::vector<Polygon2>& upper = slices.upper;
  const Point2 b = lower[0][2], c = lower[0][3];
  const Point2 inCorner{ (b.x + c.x + lower[0][1].x) / 3.0, (b.y + c.y + lower[0][1].y) / 3.0 };
  upper.push_back(circle(inCorner.x, inCorner.y, 1e-3, 8));
  EXPECT_EQ(removeVerticesNearCommonOnes(lower, nullptr, &upper, 0.15, 1e-9), 1u) << "only the vertex at -15 degrees";
  EXPECT_TRUE(hasVertex(lower[0], b));
}

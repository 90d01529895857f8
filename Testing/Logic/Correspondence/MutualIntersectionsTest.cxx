#include "ContourStacks.h"
#include "Correspondence/MutualIntersections.h"
#include "Core/PlanarGeometry.h"

#include <gtest/gtest.h>

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

// The walk along a contour by arc length that the resampling and the implicit function's samples share.
#include "Core/ArcLengthWalk.h"

#include <gtest/gtest.h>

using namespace slicemesh;

namespace
{
// A 4 x 2 rectangle, counter-clockwise from the origin: edges of 4, 2, 4, 2 mm.
const Polygon2 rectangle{ { 0.0, 0.0 }, { 4.0, 0.0 }, { 4.0, 2.0 }, { 0.0, 2.0 } };
} // namespace

TEST(ArcLengthWalk, FindsEachArcLengthOnTheFirstEdgeReachingIt)
{
  ArcLengthWalk walk(rectangle);
  ASSERT_TRUE(walk.reach(0.0));
  EXPECT_DOUBLE_EQ(walk.at(0.0).x, 0.0);
  ASSERT_TRUE(walk.reach(4.0)); // a corner belongs to the edge that ends there
  EXPECT_DOUBLE_EQ(walk.at(4.0).x, 4.0);
  EXPECT_DOUBLE_EQ(walk.at(4.0).y, 0.0);
  ASSERT_TRUE(walk.reach(5.0));
  EXPECT_DOUBLE_EQ(walk.at(5.0).x, 4.0);
  EXPECT_DOUBLE_EQ(walk.at(5.0).y, 1.0);
  ASSERT_TRUE(walk.reach(11.0));
  EXPECT_DOUBLE_EQ(walk.at(11.0).x, 0.0);
  EXPECT_DOUBLE_EQ(walk.at(11.0).y, 1.0);
  EXPECT_DOUBLE_EQ(arcLength(rectangle, 0, rectangle.size()), 12.0);
}

TEST(ArcLengthWalk, PastTheEndStaysOnTheLastEdgeAndOnlyOnEdgeAtHoldsToIt)
{
  ArcLengthWalk walk(rectangle);
  EXPECT_FALSE(walk.reach(13.0));
  EXPECT_DOUBLE_EQ(walk.at(13.0).y, -1.0); // the last edge's line, beyond its end
  EXPECT_DOUBLE_EQ(walk.onEdgeAt(13.0).x, 0.0);
  EXPECT_DOUBLE_EQ(walk.onEdgeAt(13.0).y, 0.0);
}

TEST(ArcLengthWalk, AStretchStartsAtItsPointAndWrapsRoundTheLast)
{
  // From the third point over two edges: (4, 2) -> (0, 2) -> (0, 0), 6 mm.
  EXPECT_DOUBLE_EQ(arcLength(rectangle, 2, 2), 6.0);
  ArcLengthWalk walk(rectangle, 2, 2);
  ASSERT_TRUE(walk.reach(5.0));
  EXPECT_DOUBLE_EQ(walk.at(5.0).x, 0.0);
  EXPECT_DOUBLE_EQ(walk.at(5.0).y, 1.0);
  EXPECT_FALSE(walk.reach(7.0));
}

TEST(ArcLengthWalk, AnEdgeOfNoLengthGivesItsPoint)
{
  const Polygon2 repeated{ { 1.0, 1.0 }, { 1.0, 1.0 }, { 3.0, 1.0 } };
  ArcLengthWalk walk(repeated);
  ASSERT_TRUE(walk.reach(0.0));
  EXPECT_DOUBLE_EQ(walk.at(0.0).x, 1.0);
  ASSERT_TRUE(walk.reach(1.0));
  EXPECT_DOUBLE_EQ(walk.at(1.0).x, 2.0);
}

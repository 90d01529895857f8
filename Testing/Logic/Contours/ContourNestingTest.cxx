#include "Contours/ContourNesting.h"
#include "ContourStacks.h"
#include "Core/PlanarGeometry.h"

#include <gtest/gtest.h>

using namespace slicemesh;
using namespace slicemesh::testing;

TEST(ContourNesting, OrientsByDepthAtAnyLevel)
{
  // outer > hole > island > hole in island, all given clockwise, plus a separate outer.
  std::vector<Polygon2> contours{ circle(0, 0, 10, 40, true), circle(0, 0, 7, 30, true), circle(0, 0, 4, 20, true),
                                  circle(0, 0, 2, 12, true), circle(30, 0, 3, 12, true) };
  const ContourNesting nesting = orientAndNest(contours);
  EXPECT_EQ(nesting.depth, (std::vector<int>{ 0, 1, 2, 3, 0 }));
  EXPECT_EQ(nesting.parent, (std::vector<int>{ -1, 0, 1, 2, -1 }));
  for (std::size_t i = 0; i < contours.size(); ++i)
    EXPECT_EQ(twiceSignedArea(contours[i]) > 0.0, !nesting.isHole(i)) << "contour " << i;
}

TEST(ContourNesting, AmongManyContoursEachFindsOnlyThoseAroundIt)
{
  // A slice of a thresholded noisy image: a 20 x 20 field of specks, with a ring (outer and hole)
  // around one of them and an island in a second ring's hole. Each speck's depth is the number of
  // contours around it, found among those whose boxes meet its own.
  std::vector<Polygon2> contours;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      contours.push_back(circle(10.0 * i, 10.0 * j, 1.0, 8));
  const std::size_t ringed = 5 * 20 + 7, n = contours.size();
  contours.push_back(circle(50.0, 70.0, 4.5, 32));       // n: around speck (5, 7)
  contours.push_back(circle(50.0, 70.0, 3.0, 24, true)); // n + 1: its hole, holding the speck
  contours.push_back(circle(150.0, 150.0, 4.5, 32));     // n + 2: around speck (15, 15)
  contours.push_back(circle(150.0, 150.0, 3.0, 24));     // n + 3: its hole
  contours.push_back(circle(150.0, 150.0, 2.0, 16));     // n + 4: an island in the hole, around the speck
  const ContourNesting nesting = orientAndNest(contours);
  for (std::size_t k = 0; k < n; ++k)
  {
    const int expected = k == ringed ? 2 : k == 15 * 20 + 15 ? 3 : 0;
    EXPECT_EQ(nesting.depth[k], expected) << "speck " << k;
  }
  EXPECT_EQ(nesting.parent[ringed], static_cast<int>(n + 1));
  EXPECT_EQ(nesting.parent[n + 1], static_cast<int>(n));
  EXPECT_EQ(nesting.parent[15 * 20 + 15], static_cast<int>(n + 4));
  EXPECT_EQ(nesting.parent[n + 4], static_cast<int>(n + 3));
  EXPECT_EQ(nesting.depth[n + 4], 2);
  for (std::size_t i = 0; i < contours.size(); ++i)
    EXPECT_EQ(twiceSignedArea(contours[i]) > 0.0, !nesting.isHole(i)) << "contour " << i;
}

TEST(ContourNesting, CleaningDropsDuplicatesSpikesAndSlivers)
{
  const Polygon2 messy{ { 0, 0 }, { 0, 0 }, { 2, 0 }, { 3, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 0, 0 } };
  const Polygon2 cleaned = cleanContour(messy, 1e-9);
  EXPECT_EQ(cleaned.size(), 4u);
  EXPECT_DOUBLE_EQ(std::abs(twiceSignedArea(cleaned)), 8.0);
  EXPECT_TRUE(cleanContour({ { 0, 0 }, { 1, 0 }, { 2, 0 } }, 1e-9).empty()) << "no area";
  EXPECT_TRUE(cleanContour({ { 0, 0 }, { 1, 0 } }, 1e-9).empty());
  EXPECT_THROW(cleanContour({ { 0, 0 }, { NAN, 0 }, { 1, 1 } }, 1e-9), Error);
}

TEST(PlanarGeometry, InsideIsStrictAndExact)
{
  const Polygon2 square = rectangle(0, 0, 1, 1);
  EXPECT_TRUE(isInside(square, { 0.5, 0.5 }));
  EXPECT_FALSE(isInside(square, { 1.0, 0.5 })) << "on an edge";
  EXPECT_FALSE(isInside(square, { 0.0, 0.0 })) << "on a vertex";
  EXPECT_FALSE(isInside(square, { 1.5, 0.5 }));
  EXPECT_FALSE(isInside(square, { 0.5, 1.0 })) << "on a horizontal edge";
}

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

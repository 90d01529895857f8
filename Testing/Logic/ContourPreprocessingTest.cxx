// Contour preprocessing: resampling to a point spacing, simplification within a tolerance, and
// that neither creates crossings.
#include "ContourCrossings.h"
#include "ContourResampling.h"
#include "ContourSimplification.h"
#include "PlanarGeometry.h"

#include "ContourStacks.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** A circle of n points whose radius alternates r + a, r - a: a staircase-like zigzag. */
Polygon2 zigzagCircle(double cx, double cy, double r, double a, int n)
{
  Polygon2 polygon = circle(cx, cy, r, n);
  for (int i = 0; i < n; ++i)
  {
    const double s = (i % 2 ? -a : a) / r;
    polygon[i] = { cx + (polygon[i].x - cx) * (1.0 + s), cy + (polygon[i].y - cy) * (1.0 + s) };
  }
  return polygon;
}

double distanceToPolygon(const Point2& p, const Polygon2& polygon)
{
  double d = 1e300;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    d = std::min(d, distanceToSegment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return d;
}

double perimeter(const Polygon2& polygon)
{
  double length = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    length += distance(polygon[i], polygon[(i + 1) % polygon.size()]);
  return length;
}

} // namespace

TEST(ContourCrossings, FindsCrossingsTouchesAndFoldsButNotNeighbours)
{
  EXPECT_TRUE(contourCrossings({ circle(0, 0, 5, 40) }).empty());
  EXPECT_TRUE(contourCrossings({ circle(0, 0, 5, 40), circle(0, 0, 4, 40, true) }).empty());
  // Two overlapping circles cross twice (two pairs of edges at least).
  EXPECT_GE(contourCrossings({ circle(0, 0, 5, 40), circle(6, 0, 5, 40) }).size(), 2u);
  // A bow tie crosses itself.
  EXPECT_EQ(contourCrossings({ { { 0, 0 }, { 2, 2 }, { 2, 0 }, { 0, 2 } } }).size(), 1u);
  // A contour touching another at a vertex.
  EXPECT_FALSE(contourCrossings({ rectangle(0, 0, 1, 1), rectangle(1, 1, 2, 2) }).empty());
  // A spike folding back on itself.
  EXPECT_FALSE(contourCrossings({ { { 0, 0 }, { 4, 0 }, { 2, 0 }, { 2, 2 } } }).empty());
}

TEST(ContourResampling, SpacingIsTheTargetAndTheShapeIsKept)
{
  const Polygon2 fine = circle(3, -2, 20, 2000);
  for (double spacing : { 0.5, 1.0, 2.5 })
  {
    const Polygon2 resampled = resampleContour(fine, spacing);
    const double length = perimeter(fine);
    EXPECT_EQ(resampled.size(), static_cast<std::size_t>(std::llround(length / spacing)));
    for (std::size_t i = 0; i < resampled.size(); ++i)
    {
      const double edge = distance(resampled[i], resampled[(i + 1) % resampled.size()]);
      EXPECT_NEAR(edge, length / resampled.size(), 0.01 * spacing);
      EXPECT_LT(distanceToPolygon(resampled[i], fine), 1e-9);
    }
    EXPECT_GT(twiceSignedArea(resampled), 0.0); // orientation kept
  }
  // Coarse input, fine spacing: points are added along the edges.
  const Polygon2 square = rectangle(0, 0, 10, 10);
  EXPECT_EQ(resampleContour(square, 1.0).size(), 40u);
  // Off or degenerate: unchanged.
  EXPECT_EQ(resampleContour(square, 0.0).size(), 4u);
  // A tiny contour keeps at least a triangle.
  EXPECT_EQ(resampleContour(circle(0, 0, 0.1, 12), 5.0).size(), 3u);
}

TEST(ContourResampling, ResamplesAgainFinerWhereAChordWouldCrossANeighbour)
{
  // Two concentric circles 0.3 mm apart: at a spacing of 8 mm the chords of the outer circle cut
  // into the inner one (sagitta of an 8 mm chord on r = 10: 0.8 mm).
  const std::vector<Polygon2> contours = { circle(0, 0, 10, 400), circle(0, 0, 9.7, 400, true) };
  const std::vector<Polygon2> resampled = resampleContours(contours, 8.0);
  EXPECT_TRUE(contourCrossings(resampled).empty());
  EXPECT_LT(resampled[0].size(), 400u);
  EXPECT_EQ(resampleContours(ContourStack{ { { 1.0, contours } }, 1.0 }, 8.0).slices[0].contours.size(), 2u);
}

TEST(ContourSimplification, DropsPointsWithinTheToleranceOnly)
{
  const Polygon2 zigzag = zigzagCircle(0, 0, 20, 0.25, 400);
  for (double tolerance : { 0.6, 1.0, 2.0 })
  {
    const Polygon2 simplified = simplifyContours(std::vector<Polygon2>{ zigzag }, tolerance).front();
    EXPECT_LT(simplified.size(), zigzag.size() / 2) << tolerance;
    EXPECT_GE(simplified.size(), 3u);
    for (const Point2& p : zigzag)
      EXPECT_LE(distanceToPolygon(p, simplified), tolerance + 1e-12);
    // Every kept point is an input point.
    for (const Point2& p : simplified)
      EXPECT_NE(std::find_if(zigzag.begin(), zigzag.end(), [&](const Point2& q) { return q.x == p.x && q.y == p.y; }),
                zigzag.end());
    EXPECT_GT(twiceSignedArea(simplified), 0.0);
  }
  // Tolerance 0: unchanged.
  EXPECT_EQ(simplifyContours(std::vector<Polygon2>{ zigzag }, 0.0).front().size(), zigzag.size());
  // A contour smaller than the tolerance keeps a triangle.
  EXPECT_EQ(simplifyContours(std::vector<Polygon2>{ circle(0, 0, 0.2, 20) }, 5.0).front().size(), 3u);
}

TEST(ContourSimplification, NeverCreatesCrossings)
{
  // A ring (outer and hole 0.4 mm apart) and a neighbour 0.3 mm away: plain Douglas-Peucker at
  // 1.5 mm cuts chords across the gaps.
  const std::vector<Polygon2> contours = { zigzagCircle(0, 0, 10, 0.1, 300), zigzagCircle(0, 0, 9.4, 0.1, 300),
                                           zigzagCircle(20.5, 0, 10.2, 0.1, 300) };
  ASSERT_TRUE(contourCrossings(contours).empty());
  const std::vector<Polygon2> simplified = simplifyContours(contours, 1.5);
  EXPECT_TRUE(contourCrossings(simplified).empty());
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    EXPECT_LT(simplified[c].size(), contours[c].size());
    for (const Point2& p : contours[c])
      EXPECT_LE(distanceToPolygon(p, simplified[c]), 1.5 + 1e-12);
  }
  // A stack: every slice, empty ones included.
  ContourStack stack{ { { 0.0, contours }, { 1.0, {} } }, 1.0 };
  const ContourStack out = simplifyContours(stack, 1.5);
  ASSERT_EQ(out.slices.size(), 2u);
  EXPECT_TRUE(out.slices[1].contours.empty());
  EXPECT_EQ(meanPointSpacing(ContourStack{ { { 0.0, { rectangle(0, 0, 2, 2) } } }, 1.0 }), 2.0);
}

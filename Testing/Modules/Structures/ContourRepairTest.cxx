// Slices whose contours cross, touch or run through keyholes, made into contours the tiling
// takes: the even-odd region of the slice, checked by area and by the exact crossing test.
#include "ContourRepair.h"
#include "Contours/ContourCrossings.h"
#include "Contours/ContourNesting.h"
#include "Core/PlanarGeometry.h"
#include "TestContours.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slicemesh::testing
{
namespace
{

Polygon2 flat(const Polygon3& contour)
{
  Polygon2 points;
  for (const Point3& p : contour)
    points.push_back({ p.x, p.y });
  return points;
}

/** The area the contours enclose with holes by nesting depth (they must not cross). */
double nestedArea(std::vector<Polygon2> contours)
{
  const ContourNesting nesting = orientAndNest(contours);
  double area = 0.0;
  for (std::size_t i = 0; i < contours.size(); ++i)
    area += 0.5 * std::abs(twiceSignedArea(contours[i])) * (nesting.isHole(i) ? -1.0 : 1.0);
  return area;
}

TEST(ContourRepair, AZeroWidthKeyholeBecomesAnOuterContourAndItsHole)
{
  const std::vector<Polygon2> keyhole{ flat(keyholeAnnulus(0.0, 0.0, 0.0, 20.0, 10.0, 0.0)) };
  EXPECT_FALSE(contourCrossings(keyhole).empty()) << "the channel's sides lie on each other";
  const std::vector<Polygon2> region = evenOddRegion(keyhole);
  ASSERT_EQ(region.size(), 2u);
  EXPECT_TRUE(contourCrossings(region).empty());
  const double expected = polygonArea(20.0) - polygonArea(10.0);
  EXPECT_NEAR(nestedArea(region), expected, 1e-3 * expected);
}

TEST(ContourRepair, ANarrowKeyholeIsClosedAWideNotchIsKept)
{
  ContourStack stack;
  stack.slices.push_back({ 0.0, { flat(keyholeAnnulus(0.0, 0.0, 0.0, 20.0, 10.0, 0.03)) } });
  stack.slices.push_back({ 3.0, { flat(keyholeAnnulus(0.0, 0.0, 3.0, 20.0, 10.0, 2.0)) } });
  ContourRepairReport report;
  const ContourStack repaired = repairContours(stack, {}, &report);
  ASSERT_EQ(repaired.slices[0].contours.size(), 2u) << "0.03 mm is under the 0.1 mm channel width";
  ASSERT_EQ(report.channelSlices.size(), 1u);
  EXPECT_EQ(report.channelSlices[0], 0.0);
  EXPECT_TRUE(report.crossingSlices.empty());
  ASSERT_EQ(repaired.slices[1].contours.size(), 1u) << "a 2 mm channel is real anatomy";
  EXPECT_EQ(repaired.slices[1].contours[0].size(), stack.slices[1].contours[0].size()) << "kept exactly";
  EXPECT_NE(report.summary(0.1).find("keyholes"), std::string::npos);
}

TEST(ContourRepair, AFigureEightBecomesItsTwoLobes)
{
  // A figure eight: one contour crossing itself at the origin.
  Polygon2 eight;
  for (int k = 0; k < 64; ++k)
  {
    const double t = 2.0 * Pi * k / 64;
    eight.push_back({ 10.0 * std::sin(t), 5.0 * std::sin(2.0 * t) });
  }
  ASSERT_FALSE(contourCrossings({ eight }).empty());
  ContourStack stack;
  stack.slices.push_back({ 6.0, { eight } });
  ContourRepairReport report;
  const ContourStack repaired = repairContours(stack, {}, &report);
  const std::vector<Polygon2>& lobes = repaired.slices[0].contours;
  ASSERT_EQ(lobes.size(), 2u);
  EXPECT_TRUE(contourCrossings(lobes).empty()) << "the lobes met at a point: they must come apart";
  EXPECT_NEAR(nestedArea(lobes), 0.5 * std::abs(twiceSignedArea({ eight.begin(), eight.begin() + 33 })) * 2.0, 0.5);
  EXPECT_EQ(report.crossingSlices, std::vector<double>{ 6.0 });
}

TEST(ContourRepair, OverlappingContoursFollowTheEvenOddRule)
{
  // Two squares overlapping in a 5 x 10 strip: the strip is covered twice, so it is outside.
  const Polygon2 a{ { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } };
  const Polygon2 b{ { 5, 0 }, { 15, 0 }, { 15, 10 }, { 5, 10 } };
  const std::vector<Polygon2> region = evenOddRegion({ a, b });
  EXPECT_TRUE(contourCrossings(region).empty());
  EXPECT_NEAR(nestedArea(region), 100.0, 0.1);
}

TEST(ContourRepair, AContourDrawnBackAndForthOverItselfLeavesNoCrumbs)
{
  // A circle of 20 mm whose 200 points zig-zag up to 0.5 mm across it, as a shaky hand or an
  // export's rounding draws: it crosses itself in dozens of places, and the even-odd rule leaves
  // the loops between crossings as tiny islands and holes (0.01-0.5 mm^2). Kept, they tiled into
  // folded slivers (an invalid mesh, exit 7) and, at 2 mm, runs of minutes and gigabytes. They are
  // dropped: under a square millimetre and a hundredth of the slice's largest piece.
  Polygon2 shaky;
  for (int i = 0; i < 200; ++i)
  {
    const double angle = 2.0 * M_PI * i / 200.0;
    // Each point moved by up to 0.5 mm along x and y, with no pattern along the circle.
    const double dx = ((i * 7919) % 11 - 5) * 0.1, dy = ((i * 104729) % 13 - 6) * (0.5 / 6.0);
    shaky.push_back({ 20.0 * std::cos(angle) + dx, 20.0 * std::sin(angle) + dy });
  }
  ASSERT_FALSE(contourCrossings({ shaky }).empty());
  const std::vector<Polygon2> region = evenOddRegion({ shaky });
  ASSERT_EQ(region.size(), 1u);
  EXPECT_TRUE(contourCrossings(region).empty());
  EXPECT_NEAR(nestedArea(region), M_PI * 20.0 * 20.0, 0.02 * M_PI * 20.0 * 20.0);
  // A contour of 3 mm^2 in the same slice is a structure, not a crumb: kept.
  const std::vector<Polygon2> withIsland = evenOddRegion({ shaky, flat(circle(40.0, 0.0, 0.0, 1.0, 32)) });
  EXPECT_EQ(withIsland.size(), 2u);
}

TEST(ContourRepair, APointFarBeyondAnyAnatomyIsAnErrorNotACrash)
{
  // 6.7e31 mm (a fuzzed file's coordinate): too large for the integers of the polygon booleans.
  const Polygon2 far{ { 0, 0 }, { 4, 0 }, { 6.7e31, 4 }, { 0, 4 } };
  EXPECT_THROW(evenOddRegion({ far }), Error);
  const Polygon2 notANumber{ { 0, 0 }, { 4, 0 }, { std::nan(""), 4 }, { 0, 4 } };
  EXPECT_THROW(evenOddRegion({ notANumber }), Error);
  EXPECT_NO_THROW(evenOddRegion({ Polygon2{ { 9e5, 0 }, { 9e5 + 4, 0 }, { 9e5 + 4, 4 }, { 9e5, 4 } } }));
  // A slice repaired or kept as given alike: the point is an error, not passed on to the tiling.
  for (const Polygon2& bad : { far, notANumber })
  {
    ContourStack stack;
    stack.slices.push_back({ 0.0, { bad } });
    EXPECT_THROW(repairContours(stack), Error);
  }
}

TEST(ContourRepair, CleanSlicesAreKeptExactly)
{
  ContourStack stack;
  stack.slices.push_back({ 0.0, { flat(circle(0, 0, 0, 20.0)), flat(circle(0, 0, 0, 10.0, 96, true)),
                                  flat(circle(50, 0, 0, 5.0)) } });
  ContourRepairReport report;
  const ContourStack repaired = repairContours(stack, {}, &report);
  EXPECT_FALSE(report.any());
  ASSERT_EQ(repaired.slices[0].contours.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < repaired.slices[0].contours[c].size(); ++i)
    {
      EXPECT_EQ(repaired.slices[0].contours[c][i].x, stack.slices[0].contours[c][i].x);
      EXPECT_EQ(repaired.slices[0].contours[c][i].y, stack.slices[0].contours[c][i].y);
    }
}

TEST(ContourRepair, EdgesWithinAGapAreFoundOnlyCloserThanIt)
{
  // Two squares 0.2 mm apart along x: no edges within 0.15 mm, seven pairs within 0.25 mm.
  const Polygon2 a{ { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } };
  const Polygon2 b{ { 10.2, 0 }, { 20, 0 }, { 20, 10 }, { 10.2, 10 } };
  EXPECT_TRUE(contourEdgesWithin({ a, b }, 0.15).empty());
  // Within 0.25: a's right side with b's left, bottom and top; a's bottom and top with b's left and
  // with the side of b they are collinear with (their ends 0.2 apart).
  const auto close = contourEdgesWithin({ a, b }, 0.25);
  EXPECT_EQ(close.size(), 7u);
  for (const auto& [e, f] : close)
    EXPECT_NE(e.contour, f.contour);
  EXPECT_TRUE(contourEdgesWithin({ a }, 9.9).empty()) << "consecutive sides are left out, opposite ones are 10 apart";
  EXPECT_EQ(contourEdgesWithin({ a }, 10.0).size(), 2u);
  EXPECT_TRUE(contourCrossings({ a, b }).empty());
}

TEST(ContourRepair, ADenselySampledContourIsKeptAsGivenUnlessItCrossesItself)
{
  // 20,000 points on a 20 mm circle, 0.006 mm apart: every edge is within the channel width of the
  // next but one. Such neighbours along the contour are no channel: the slice is kept exactly, not
  // run through the closing (whose strictly-simple pass is quadratic in the points: a 100,000-point
  // contour took 20 s). Two points swapped still make a loop that is repaired.
  const Polygon2 dense = flat(circle(0.0, 0.0, 0.0, 20.0, 20000));
  ContourStack stack;
  stack.slices.push_back({ 0.0, { dense } });
  ContourRepairReport report;
  const ContourStack kept = repairContours(stack, {}, &report);
  EXPECT_FALSE(report.any());
  EXPECT_EQ(kept.slices[0].contours[0].size(), dense.size());
  Polygon2 looped = dense;
  std::swap(looped[100], looped[102]);
  stack.slices[0].contours = { looped };
  repairContours(stack, {}, &report);
  EXPECT_EQ(report.crossingSlices.size(), 1u);
}

TEST(ContourRepair, SlicesAreKeptWithoutClosingOnlyWhereClosingCannotChangeThem)
{
  // Two circles, a keyhole and a spike at gaps on both sides of the 0.1 mm channel width: wherever
  // no edges come within the width, closing keeps every contour (so the slice may be kept as
  // given), and well below the width the slice is still repaired.
  for (double gap : { 0.02, 0.05, 0.09, 0.099, 0.101, 0.104, 0.11, 0.2, 0.5, 2.0 })
  {
    const std::vector<Polygon2> twoCircles{ flat(circle(0, 0, 0, 5.0)), flat(circle(10.0 + gap, 0, 0, 5.0)) };
    const std::vector<Polygon2> keyhole{ flat(keyholeAnnulus(0.0, 0.0, 0.0, 20.0, 10.0, gap)) };
    // A spike of about 11 degrees, whose offset corner reaches far beyond its tip, pointing at a square.
    const std::vector<Polygon2> spike{ { { -10, -1 }, { -gap, 0 }, { -10, 1 } },
                                       { { 0, -5 }, { 10, -5 }, { 10, 5 }, { 0, 5 } } };
    const std::vector<const std::vector<Polygon2>*> cases{ &twoCircles, &keyhole, &spike };
    for (const std::vector<Polygon2>* tried : cases)
    {
      const std::vector<Polygon2>& contours = *tried;
      if (contourEdgesWithin(contours, 0.1 + 3e-3).empty())
        EXPECT_EQ(evenOddRegion(contours).size(), contours.size()) << "gap " << gap;
      ContourStack stack;
      stack.slices.push_back({ 0.0, contours });
      ContourRepairReport report;
      const ContourStack repaired = repairContours(stack, {}, &report);
      // Nearer the width the closing's own rounding decides; a spike's tip is too narrow to bridge.
      if (gap <= 0.05 && tried != &spike)
      {
        EXPECT_NE(repaired.slices[0].contours.size(), contours.size()) << "gap " << gap;
        EXPECT_EQ(report.channelSlices.size(), 1u) << "gap " << gap;
      }
      else if (gap > 0.11)
        EXPECT_FALSE(report.any()) << "gap " << gap;
    }
  }
}

} // namespace
} // namespace slicemesh::testing

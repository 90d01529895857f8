// Planar contours in 3-D as a contour stack: the slice normal from the contours, slices along it,
// the frame that maps the stack back onto the contours, and the faults of real structure sets
// (uneven spacing, missing slices, duplicates, tilted contours, a single slice).
#include "Contours/ContourStacking.h"
#include "Core/PlanarGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slicemesh
{
namespace
{

constexpr double Pi = 3.14159265358979323846;

/** A square of side 2a about centre c in the plane spanned by unit vectors e1, e2. */
Polygon3 square(const Vector3& c, const Vector3& e1, const Vector3& e2, double a)
{
  Polygon3 points;
  for (const auto& [s, t] : { std::pair{ -1.0, -1.0 }, { 1.0, -1.0 }, { 1.0, 1.0 }, { -1.0, 1.0 } })
    points.push_back({ c[0] + a * (s * e1[0] + t * e2[0]), c[1] + a * (s * e1[1] + t * e2[1]),
                       c[2] + a * (s * e1[2] + t * e2[2]) });
  return points;
}

Point3 toPhysical(const SliceFrame& frame, double x, double y, double z)
{
  const auto& d = frame.direction;
  return { frame.origin[0] + d[0][0] * x + d[0][1] * y + d[0][2] * z,
           frame.origin[1] + d[1][0] * x + d[1][1] * y + d[1][2] * z,
           frame.origin[2] + d[2][0] * x + d[2][1] * y + d[2][2] * z };
}

bool mentions(const std::vector<std::string>& notes, const std::string& word)
{
  for (const std::string& note : notes)
    if (note.find(word) != std::string::npos)
      return true;
  return false;
}

TEST(ContourStacking, NewellNormalIsTwiceTheAreaAlongThePlaneNormal)
{
  const Vector3 n = newellNormal(square({ 100.0, -50.0, 7.0 }, { 1, 0, 0 }, { 0, 1, 0 }, 2.0));
  EXPECT_NEAR(n[0], 0.0, 1e-12);
  EXPECT_NEAR(n[1], 0.0, 1e-12);
  EXPECT_NEAR(n[2], 2.0 * 16.0, 1e-9); // counter-clockwise seen from +z: +z, twice the 16 mm^2
}

TEST(ContourStacking, ASymmetricFigureEightStillSpansItsPlane)
{
  // A bow tie: two triangular lobes of 8 mm^2 wound opposite ways through one crossing. Newell's
  // normal cancels, and the contour (two lobes by the even-odd rule) was dropped as one without an
  // area; an ROI of only such contours failed with "the slice plane is undefined".
  auto figureEight = [](double z) { return Polygon3{ { -4, -2, z }, { 4, 2, z }, { 4, -2, z }, { -4, 2, z } }; };
  auto length = [](const Vector3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  EXPECT_LT(length(newellNormal(figureEight(0.0))), 1e-9);
  const Vector3 n = planeNormal(figureEight(0.0));
  EXPECT_NEAR(std::abs(n[2]), length(n), 1e-12);
  EXPECT_NEAR(length(n), 2.0 * 16.0, 1e-9); // twice the two lobes' area
  const StackedContours stacked = stackContours({ figureEight(0.0), figureEight(2.5), figureEight(5.0) });
  ASSERT_EQ(stacked.stack.slices.size(), 3u);
  for (const Slice& slice : stacked.stack.slices)
    EXPECT_EQ(slice.contours.size(), 1u);
}

TEST(ContourStacking, AxialContoursKeepThePatientAxesAndTheirPositions)
{
  std::vector<Polygon3> contours;
  for (int k = 0; k < 4; ++k) // windings alternate: they must not matter
  {
    Polygon3 s = square({ 10.0, 20.0, -30.0 + 2.5 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0);
    if (k % 2)
      std::reverse(s.begin(), s.end());
    contours.push_back(s);
  }
  const StackedContours stacked = stackContours(contours);
  ASSERT_EQ(stacked.stack.slices.size(), 4u);
  EXPECT_NEAR(stacked.stack.sliceSpacing, 2.5, 1e-12);
  EXPECT_EQ(stacked.contoursUsed, 4u);
  EXPECT_TRUE(stacked.notes.empty());
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      EXPECT_NEAR(stacked.frame.direction[row][column], row == column ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(stacked.stack.slices[0].z, -30.0, 1e-12);
  EXPECT_NEAR(stacked.spacing[2], 2.5, 1e-12);
}

TEST(ContourStacking, ObliqueContoursMapBackExactlyThroughTheFrame)
{
  // Slices tilted 30 degrees about x and 20 about z: every point must come back to where it was.
  const double a = 30.0 * Pi / 180.0, b = 20.0 * Pi / 180.0;
  const Vector3 e1{ std::cos(b), std::sin(b), 0.0 };
  const Vector3 e2{ -std::sin(b) * std::cos(a), std::cos(b) * std::cos(a), std::sin(a) };
  const Vector3 normal{ e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
  std::vector<Polygon3> contours;
  for (int k = 0; k < 5; ++k)
    contours.push_back(square({ 40.0 + 3.0 * k * normal[0], -120.0 + 3.0 * k * normal[1], 300.0 + 3.0 * k * normal[2] },
                              e1, e2, 4.0 + k));
  const StackedContours stacked = stackContours(contours);
  ASSERT_EQ(stacked.stack.slices.size(), 5u);
  EXPECT_NEAR(stacked.stack.sliceSpacing, 3.0, 1e-9);
  double worst = 0.0;
  for (std::size_t k = 0; k < 5; ++k)
  {
    const Slice& slice = stacked.stack.slices[k];
    ASSERT_EQ(slice.contours.size(), 1u);
    for (std::size_t i = 0; i < 4; ++i)
    {
      const Point3 p = toPhysical(stacked.frame, slice.contours[0][i].x, slice.contours[0][i].y, slice.z);
      const Point3& q = contours[k][i];
      worst = std::max(worst, std::hypot(p.x - q.x, p.y - q.y, p.z - q.z));
    }
  }
  EXPECT_LT(worst, 1e-9) << "the frame must put the contours back where they were";
  // The frame is orthonormal and right-handed.
  const auto& d = stacked.frame.direction;
  const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                     d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  EXPECT_NEAR(det, 1.0, 1e-12);
}

TEST(ContourStacking, ATiltedContourAmongAxialOnesIsSkippedAndTheNormalStaysAxial)
{
  std::vector<Polygon3> contours;
  for (int k = 0; k < 6; ++k)
    contours.push_back(square({ 0.0, 0.0, 3.0 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 10.0));
  contours.push_back(square({ 0.0, 0.0, 7.0 }, { 1, 0, 0 }, { 0, 0, 1 }, 3.0)); // a coronal stray
  const Vector3 normal = sliceNormalOf(contours);
  EXPECT_NEAR(normal[2], 1.0, 1e-12);
  const StackedContours stacked = stackContours(contours);
  EXPECT_EQ(stacked.contoursUsed, 6u);
  EXPECT_TRUE(mentions(stacked.notes, "tilted")) << "the skipped contour must be reported";
}

TEST(ContourStacking, AContourNotFlatIsSaidAndOneTiltedButFlatIsNot)
{
  // Circles of 32 points every 3 mm: one whose points go up and down by 0.5 mm, one tilted by 3
  // degrees (within the tilt allowed), flat.
  auto circle = [](double z, double wobble, double tilt)
  {
    Polygon3 points;
    for (int i = 0; i < 32; ++i)
    {
      const double a = 2.0 * Pi * i / 32.0, x = 20.0 * std::cos(a), y = 20.0 * std::sin(a);
      points.push_back({ x, y, z + (i % 2 ? wobble : -wobble) + x * std::tan(tilt * Pi / 180.0) });
    }
    return points;
  };
  std::vector<Polygon3> flat;
  for (int k = 0; k < 6; ++k)
    flat.push_back(circle(3.0 * k, 0.0, k == 3 ? 3.0 : 0.0));
  const StackedContours tilted = stackContours(flat);
  EXPECT_EQ(tilted.contoursUsed, 6u);
  EXPECT_FALSE(mentions(tilted.notes, "not flat"));
  std::vector<Polygon3> wobbling = flat;
  wobbling[2] = circle(6.0, 0.5, 0.0);
  const StackedContours stacked = stackContours(wobbling);
  EXPECT_EQ(stacked.contoursUsed, 6u);
  EXPECT_TRUE(mentions(stacked.notes, "1 contour(s) not flat: points up to 0.5 mm off their own plane"))
    << (stacked.notes.empty() ? "" : stacked.notes.front());
}

TEST(ContourStacking, ContoursOfOneSliceGroupDespiteSmallOffsetsAndDuplicatesAreDropped)
{
  std::vector<Polygon3> contours;
  for (int k = 0; k < 3; ++k)
  {
    contours.push_back(square({ -20.0, 0.0, 3.0 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0));
    contours.push_back(square({ 20.0, 0.0, 3.0 * k + 0.004 }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0)); // planner rounding
  }
  Polygon3 repeated = contours[2];
  std::rotate(repeated.begin(), repeated.begin() + 2, repeated.end()); // same polygon, other start
  contours.push_back(repeated);
  const StackedContours stacked = stackContours(contours);
  ASSERT_EQ(stacked.stack.slices.size(), 3u);
  for (const Slice& slice : stacked.stack.slices)
    EXPECT_EQ(slice.contours.size(), 2u);
  EXPECT_TRUE(mentions(stacked.notes, "repeated"));
}

TEST(ContourStacking, PointsStoredTwiceInARowAreOnePoint)
{
  // Some exports store every point twice, and most repeat the first at the end: edges of no length,
  // which the repair would take for keyholes.
  std::vector<Polygon3> contours;
  for (int k = 0; k < 3; ++k)
  {
    Polygon3 doubled;
    for (const Point3& p : square({ 0.0, 0.0, 2.5 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0))
      doubled.insert(doubled.end(), { p, p });
    doubled.push_back(doubled.front());
    contours.push_back(doubled);
  }
  const StackedContours stacked = stackContours(contours);
  ASSERT_EQ(stacked.stack.slices.size(), 3u);
  for (const Slice& slice : stacked.stack.slices)
  {
    ASSERT_EQ(slice.contours.size(), 1u);
    ASSERT_EQ(slice.contours[0].size(), 4u);
    EXPECT_NEAR(std::abs(twiceSignedArea(slice.contours[0])), 200.0, 1e-9);
  }
}

TEST(ContourStacking, UnevenSpacingIsToleratedAndReported)
{
  std::vector<Polygon3> contours;
  for (double z : { 0.0, 2.9, 6.1, 9.0, 12.0 })
    contours.push_back(square({ 0.0, 0.0, z }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0));
  const StackedContours stacked = stackContours(contours);
  EXPECT_EQ(stacked.stack.slices.size(), 5u);
  EXPECT_NEAR(stacked.stack.sliceSpacing, 2.95, 0.06); // the median gap
  EXPECT_TRUE(mentions(stacked.notes, "uneven"));
}

TEST(ContourStacking, ASliceBetweenTwoOneSpacingApartIsSaidToSplitWhatItDoesNotHold)
{
  // A square on every 2.5 mm slice and a small one beside it at 13.75 mm, between two of them: the
  // square is closed on both sides of that slice, and a note says so.
  std::vector<Polygon3> contours;
  for (int k = 0; k <= 10; ++k)
    contours.push_back(square({ 0.0, 0.0, 2.5 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 10.0));
  std::vector<Polygon3> between = contours;
  between.push_back(square({ 40.0, 0.0, 13.75 }, { 1, 0, 0 }, { 0, 1, 0 }, 2.0));
  const StackedContours stacked = stackContours(between);
  EXPECT_NEAR(stacked.stack.sliceSpacing, 2.5, 1e-12);
  EXPECT_TRUE(mentions(stacked.notes, "the slice at 13.75 mm lies between the slices at 12.5 mm and 15 mm"))
    << (stacked.notes.empty() ? std::string() : stacked.notes.back());
  // As well 0.3 mm above a slice, past the 0.25 mm that would make it one with it.
  std::vector<Polygon3> near = contours;
  near.push_back(square({ 40.0, 0.0, 12.8 }, { 1, 0, 0 }, { 0, 1, 0 }, 2.0));
  EXPECT_TRUE(mentions(stackContours(near).notes, "the slice at 12.8 mm lies between"));
  // Two between one pair, and a stretch drawn on half-spacing slices: one note, counting them all.
  std::vector<Polygon3> two = contours;
  for (double z : { 13.3, 14.1 })
    two.push_back(square({ 40.0, 0.0, z }, { 1, 0, 0 }, { 0, 1, 0 }, 2.0));
  EXPECT_TRUE(mentions(stackContours(two).notes, "2 slices lie between two slices one spacing apart, the first at 13.3 mm "
                                                 "between the slices at 12.5 mm and 15 mm"));
  std::vector<Polygon3> halves = contours;
  for (double z : { 3.75, 6.25, 8.75 })
    halves.push_back(square({ 0.0, 0.0, z }, { 1, 0, 0 }, { 0, 1, 0 }, 10.0));
  const StackedContours halved = stackContours(halves);
  std::size_t betweenNotes = 0;
  for (const std::string& note : halved.notes)
    betweenNotes += note.find("lie between") != std::string::npos || note.find("lies between") != std::string::npos;
  EXPECT_EQ(betweenNotes, 1u);
  EXPECT_TRUE(mentions(halved.notes, "5 slices lie between two slices one spacing apart, the first at 3.75 mm between the slices at 2.5 mm and 5 mm"));
  // Evenly spaced, or merely uneven (2.9 and 3.2 mm gaps): nothing between.
  EXPECT_FALSE(mentions(stackContours(contours).notes, "lies between"));
  std::vector<Polygon3> uneven;
  for (double z : { 0.0, 2.9, 6.1, 9.0, 12.0 })
    uneven.push_back(square({ 0.0, 0.0, z }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0));
  EXPECT_FALSE(mentions(stackContours(uneven).notes, "lies between"));
}

TEST(ContourStacking, OneMissingSliceIsTiledAcrossALongerGapClosesEachSide)
{
  std::vector<Polygon3> contours;
  for (double z : { 0.0, 3.0, 6.0, 12.0, 15.0, 27.0, 30.0 }) // one slice missing at 9, three at 18-24
    contours.push_back(square({ 0.0, 0.0, z }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0));
  const StackedContours stacked = stackContours(contours);
  EXPECT_NEAR(stacked.stack.sliceSpacing, 3.0, 1e-12);
  std::size_t empty = 0;
  for (const Slice& slice : stacked.stack.slices)
    empty += slice.contours.empty() ? 1 : 0;
  EXPECT_EQ(empty, 3u) << "the slices at 18, 21 and 24 mm are empty; 9 mm is tiled across";
  EXPECT_EQ(stacked.stack.slices.size(), 10u);
  EXPECT_TRUE(mentions(stacked.notes, "one slice missing"));
  EXPECT_TRUE(mentions(stacked.notes, "stops and starts again"));
}

TEST(ContourStacking, ASingleSliceNeedsASpacingFromElsewhere)
{
  const std::vector<Polygon3> one{ square({ 0.0, 0.0, 5.0 }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0) };
  EXPECT_THROW(stackContours(one), Error);
  ContourStackingOptions options;
  options.fallbackSliceSpacing = 2.0;
  const StackedContours stacked = stackContours(one, options);
  EXPECT_EQ(stacked.stack.slices.size(), 1u);
  EXPECT_EQ(stacked.stack.sliceSpacing, 2.0);
  EXPECT_TRUE(mentions(stacked.notes, "one slice"));
}

TEST(ContourStacking, TheImageSliceDirectionAndSpacingAreUsedWhenTheContoursLieOnItsSlices)
{
  // Contours on an oblique image's slices, written with the planner's rounding to 0.01 mm: the
  // image's direction is exact, theirs an estimate; a gap of two image slices is one missing slice.
  const double a = 25.0 * Pi / 180.0;
  const Vector3 e1{ 1.0, 0.0, 0.0 }, e2{ 0.0, std::cos(a), std::sin(a) }, normal{ 0.0, -std::sin(a), std::cos(a) };
  std::vector<Polygon3> contours;
  for (double k : { 0.0, 1.0, 3.0, 4.0 })
  {
    Polygon3 s = square({ 5.0 + 2.5 * k * normal[0], 2.5 * k * normal[1], 2.5 * k * normal[2] }, e1, e2, 6.0);
    for (Point3& p : s)
      p = { std::round(p.x * 100.0) / 100.0, std::round(p.y * 100.0) / 100.0, std::round(p.z * 100.0) / 100.0 };
    contours.push_back(s);
  }
  ContourStackingOptions options;
  options.sliceNormal = Vector3{ 0.0, 2.0 * std::sin(a), -2.0 * std::cos(a) }; // any length, either sign
  options.expectedSliceSpacing = 2.5;
  const StackedContours stacked = stackContours(contours, options);
  ASSERT_TRUE(stacked.normalDeviationDegrees.has_value());
  EXPECT_LT(*stacked.normalDeviationDegrees, 0.2);
  EXPECT_TRUE(stacked.givenNormalUsed);
  for (int row = 0; row < 3; ++row)
    EXPECT_NEAR(std::abs(stacked.frame.direction[row][2]), std::abs(normal[row]), 1e-12) << "the image's normal exactly";
  EXPECT_EQ(stacked.stack.sliceSpacing, 2.5);
  EXPECT_EQ(stacked.stack.slices.size(), 4u) << "the gap of two image slices is tiled across";
  EXPECT_TRUE(mentions(stacked.notes, "one slice missing"));

  // Without the image the same contours have a median gap of 2.5 too, but only an estimated normal.
  const StackedContours own = stackContours(contours);
  EXPECT_FALSE(own.normalDeviationDegrees.has_value());
  EXPECT_FALSE(own.givenNormalUsed);
}

TEST(ContourStacking, ContoursOffTheImageSlicesFollowTheirOwnNormalAndSpacing)
{
  std::vector<Polygon3> contours;
  for (int k = 0; k < 4; ++k)
    contours.push_back(square({ 0.0, 0.0, 4.0 * k }, { 1, 0, 0 }, { 0, 1, 0 }, 5.0));
  ContourStackingOptions options;
  const double tilt = 3.0 * Pi / 180.0; // over the 1 degree allowed
  options.sliceNormal = Vector3{ std::sin(tilt), 0.0, std::cos(tilt) };
  options.expectedSliceSpacing = 2.0; // off the image's slices, its spacing says nothing
  const StackedContours stacked = stackContours(contours, options);
  ASSERT_TRUE(stacked.normalDeviationDegrees.has_value());
  EXPECT_NEAR(*stacked.normalDeviationDegrees, 3.0, 1e-9);
  EXPECT_FALSE(stacked.givenNormalUsed);
  EXPECT_NEAR(stacked.frame.direction[2][2], 1.0, 1e-12) << "the contours' own normal";
  EXPECT_NEAR(stacked.stack.sliceSpacing, 4.0, 1e-12) << "the contours' own spacing";

  // On the image's planes but never one of its slices apart: their own spacing, with a note.
  ContourStackingOptions parallel;
  parallel.sliceNormal = Vector3{ 0.0, 0.0, 1.0 };
  parallel.expectedSliceSpacing = 3.0;
  const StackedContours sparse = stackContours(contours, parallel);
  EXPECT_TRUE(sparse.givenNormalUsed);
  EXPECT_NEAR(sparse.stack.sliceSpacing, 4.0, 1e-12);
  EXPECT_TRUE(mentions(sparse.notes, "their own spacing"));

  // A single slice takes the image's spacing as its thickness.
  ContourStackingOptions single;
  single.expectedSliceSpacing = 2.0;
  const StackedContours slab = stackContours({ contours.front() }, single);
  EXPECT_EQ(slab.stack.sliceSpacing, 2.0);
}

TEST(ContourStacking, TheCoordinateStepIsTheRoundingTheCoordinatesWereWrittenWith)
{
  const auto stepOf = [](std::vector<double> coordinates)
  {
    Polygon3 contour;
    for (std::size_t i = 0; i + 2 < coordinates.size(); i += 3)
      contour.push_back({ coordinates[i], coordinates[i + 1], coordinates[i + 2] });
    return coordinateStep({ contour });
  };
  EXPECT_EQ(stepOf({ 12.0, -40.0, 300.0 }), 1.0);
  EXPECT_DOUBLE_EQ(stepOf({ 12.5, -40.25, 300.0, 1.0, 2.0, -0.75 }), 0.01);
  // Six decimals, as a DICOM decimal string holds them, far from the origin too.
  EXPECT_DOUBLE_EQ(stepOf({ 18.477591, -7.64318, 1234.567891, -0.400562, 20.0, -1e-6 }), 1e-6);
  EXPECT_DOUBLE_EQ(stepOf({ 1e5 + 0.001, 2.5, -3.125 }), 1e-3);
  // Single precision (3D Slicer's planar contours): its spacing at the largest coordinate.
  const volatile float fx = static_cast<float>(20.0 * std::cos(0.3)), fy = static_cast<float>(-300.0 * std::sin(0.3));
  const double x = fx, y = fy;
  EXPECT_DOUBLE_EQ(stepOf({ x, y, 2.5 }), std::abs(y) * std::numeric_limits<float>::epsilon());
  // Not rounded: as computed, or with more decimals than nine.
  EXPECT_EQ(stepOf({ 20.0 * std::cos(0.3), 20.0 * std::sin(0.3), 2.5 }), 0.0);
  EXPECT_EQ(stepOf({ 0.1234567891, 1.0, 2.0 }), 0.0);
  // The stack carries it.
  std::vector<Polygon3> contours;
  for (int k = 0; k < 3; ++k)
    contours.push_back({ { 0.0, 0.0, 2.5 * k }, { 10.25, 0.0, 2.5 * k }, { 10.25, 10.5, 2.5 * k } });
  EXPECT_DOUBLE_EQ(stackContours(contours).stack.coordinateStep, 0.01);
}

TEST(ContourStacking, ContoursWithoutAreaAreNoSlicePlane)
{
  const std::vector<Polygon3> lines{ { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } } };
  EXPECT_THROW(sliceNormalOf(lines), Error);
  EXPECT_THROW(stackContours(lines), Error);
}

} // namespace
} // namespace slicemesh

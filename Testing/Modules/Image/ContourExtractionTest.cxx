#include "ContourExtraction.h"
#include "TestVolumes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace slicemesh
{
namespace
{

using testing::makeMask;
using testing::setVoxel;

double signedArea(const Polygon2& polygon)
{
  double twice = 0.0;
  for (std::size_t n = 0; n < polygon.size(); ++n)
  {
    const Point2& a = polygon[n];
    const Point2& b = polygon[(n + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

double orientation(const Point2& a, const Point2& b, const Point2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/** Whether the closed segments ab and cd share a point (collinear overlaps included). */
bool segmentsTouch(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  auto onSegment = [](const Point2& p, const Point2& q, const Point2& r) {
    return orientation(p, q, r) == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  };
  return onSegment(a, b, c) || onSegment(a, b, d) || onSegment(c, d, a) || onSegment(c, d, b);
}

/** No two contours of the slice touch, and no contour touches itself except at shared vertices
 *  of consecutive edges. */
void expectSimpleAndSeparate(const Slice& slice)
{
  for (std::size_t p = 0; p < slice.contours.size(); ++p)
    for (std::size_t q = p; q < slice.contours.size(); ++q)
    {
      const Polygon2& first = slice.contours[p];
      const Polygon2& second = slice.contours[q];
      for (std::size_t a = 0; a < first.size(); ++a)
        for (std::size_t b = 0; b < second.size(); ++b)
        {
          const std::size_t na = first.size(), nb = second.size();
          if (p == q && (a == b || (a + 1) % na == b || (b + 1) % nb == a))
            continue; // the same or neighbouring edges of one contour share a vertex by design
          EXPECT_FALSE(segmentsTouch(first[a], first[(a + 1) % na], second[b], second[(b + 1) % nb]))
            << "contours " << p << " and " << q << " touch at edges " << a << " and " << b;
        }
    }
}

bool containsPoint(const Polygon2& polygon, double x, double y)
{
  return std::any_of(polygon.begin(), polygon.end(), [x, y](const Point2& p) { return p.x == x && p.y == y; });
}

TEST(ContourExtraction, SingleVoxelGivesADiamondAroundItsCentre)
{
  auto mask = makeMask({ 7, 7, 1 });
  setVoxel(mask.GetPointer(), 3, 4, 0, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_EQ(stack.slices.size(), 1u);
  ASSERT_EQ(stack.slices[0].contours.size(), 1u);
  const Polygon2& diamond = stack.slices[0].contours[0];
  ASSERT_EQ(diamond.size(), 4u); // the closing point is not repeated
  EXPECT_TRUE(containsPoint(diamond, 2.5, 4.0));
  EXPECT_TRUE(containsPoint(diamond, 3.5, 4.0));
  EXPECT_TRUE(containsPoint(diamond, 3.0, 3.5));
  EXPECT_TRUE(containsPoint(diamond, 3.0, 4.5));
  EXPECT_DOUBLE_EQ(std::abs(signedArea(diamond)), 0.5);
}

TEST(ContourExtraction, RectangleAreaIsVoxelCountMinusCornerCuts)
{
  auto mask = makeMask({ 10, 9, 1 });
  for (long j = 3; j <= 5; ++j)
    for (long i = 2; i <= 5; ++i)
      setVoxel(mask.GetPointer(), i, j, 0, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_EQ(stack.slices[0].contours.size(), 1u);
  const Polygon2& rectangle = stack.slices[0].contours[0];
  EXPECT_EQ(rectangle.size(), 2u * (4 + 3)); // one point per boundary voxel face
  // 12 voxels, each of the 4 corners cut by a right triangle with legs 1/2: area 1/8.
  EXPECT_EQ(std::abs(signedArea(rectangle)), 12.0 - 4 * 0.125);
}

TEST(ContourExtraction, MaskTouchingTheBorderGivesClosedContourOnTheBorder)
{
  auto mask = makeMask({ 5, 5, 1 });
  for (long j = 0; j < 5; ++j)
    for (long i = 0; i < 2; ++i)
      setVoxel(mask.GetPointer(), i, j, 0, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_EQ(stack.slices[0].contours.size(), 1u);
  const Polygon2& contour = stack.slices[0].contours[0];
  double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
  for (const Point2& p : contour)
  {
    minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
    minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
  }
  // Half a voxel beyond the outer voxel centres: the padding ring of zeros closes it there.
  EXPECT_EQ(minX, -0.5);
  EXPECT_EQ(maxX, 1.5);
  EXPECT_EQ(minY, -0.5);
  EXPECT_EQ(maxY, 4.5);
  EXPECT_EQ(contour.size(), 2u * (2 + 5));
  EXPECT_EQ(std::abs(signedArea(contour)), 10.0 - 0.5);
}

TEST(ContourExtraction, AnisotropicSpacingScalesCoordinates)
{
  auto mask = makeMask({ 8, 8, 3 }, { 0.8, 0.5, 3.0 });
  for (long j = 3; j <= 5; ++j)
    for (long i = 2; i <= 5; ++i)
      setVoxel(mask.GetPointer(), i, j, 2, 1);
  const ContourStack stack = extractContours(mask);
  EXPECT_DOUBLE_EQ(stack.sliceSpacing, 3.0);
  ASSERT_EQ(stack.slices.size(), 3u);
  EXPECT_DOUBLE_EQ(stack.slices[2].z, 6.0);
  ASSERT_EQ(stack.slices[2].contours.size(), 1u);
  const Polygon2& contour = stack.slices[2].contours[0];
  EXPECT_TRUE(containsPoint(contour, 1.5 * 0.8, 4.0 * 0.5)); // left face, middle row
  EXPECT_TRUE(containsPoint(contour, 3.0 * 0.8, 5.5 * 0.5)); // top face
  EXPECT_NEAR(std::abs(signedArea(contour)), (12.0 - 0.5) * 0.8 * 0.5, 1e-12);
}

TEST(ContourExtraction, EverySliceIsInTheStackEmptyOnesIncluded)
{
  auto mask = makeMask({ 6, 6, 4 }, { 1.0, 1.0, 2.5 });
  setVoxel(mask.GetPointer(), 2, 2, 0, 1);
  setVoxel(mask.GetPointer(), 3, 3, 3, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_EQ(stack.slices.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_DOUBLE_EQ(stack.slices[k].z, 2.5 * k);
  EXPECT_EQ(stack.slices[0].contours.size(), 1u);
  EXPECT_TRUE(stack.slices[1].contours.empty());
  EXPECT_TRUE(stack.slices[2].contours.empty());
  EXPECT_EQ(stack.slices[3].contours.size(), 1u);
}

TEST(ContourExtraction, TwoBlobsAndARingGiveSeparateNonCrossingContours)
{
  auto mask = makeMask({ 16, 10, 1 });
  for (long j = 2; j <= 4; ++j) // a 3x3 blob
    for (long i = 1; i <= 3; ++i)
      setVoxel(mask.GetPointer(), i, j, 0, 1);
  for (long j = 2; j <= 6; ++j) // a 5x5 ring around one empty voxel
    for (long i = 6; i <= 10; ++i)
      if (!(i == 8 && j == 4))
        setVoxel(mask.GetPointer(), i, j, 0, 1);
  setVoxel(mask.GetPointer(), 13, 8, 0, 1); // a lone voxel
  const ContourStack stack = extractContours(mask);
  const Slice& slice = stack.slices[0];
  ASSERT_EQ(slice.contours.size(), 4u); // blob, ring outside, ring hole, lone voxel
  expectSimpleAndSeparate(slice);

  // The hole runs the other way round from the outer boundaries.
  std::vector<double> areas;
  for (const Polygon2& contour : slice.contours)
    areas.push_back(signedArea(contour));
  std::sort(areas.begin(), areas.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  EXPECT_DOUBLE_EQ(std::abs(areas[0]), 0.5); // the hole: one voxel's diamond
  EXPECT_DOUBLE_EQ(std::abs(areas[1]), 0.5); // the lone voxel
  EXPECT_LT(areas[0] * areas[1], 0.0);
  EXPECT_DOUBLE_EQ(std::abs(areas[2]), 9.0 - 0.5);
  EXPECT_DOUBLE_EQ(std::abs(areas[3]), 25.0 - 0.5);
}

TEST(ContourExtraction, OuterContoursRunCounterClockwiseInTheStackFrame)
{
  // ITK's convention ("clockwise around hills" with j pointing down on screen) is counter-
  // clockwise with y up, as DESIGN.md wants; Logic orients contours itself all the same.
  auto mask = makeMask({ 5, 5, 1 });
  setVoxel(mask.GetPointer(), 2, 2, 0, 1);
  const ContourStack stack = extractContours(mask);
  EXPECT_GT(signedArea(stack.slices[0].contours[0]), 0.0);
}

TEST(ContourExtraction, ShrinkingSlicesDoNotSeeEarlierSlices)
{
  // Every slice is traced in a buffer sized to its foreground; a smaller slice after a larger one
  // must not pick up what the larger one left in that buffer.
  auto mask = makeMask({ 40, 40, 12 });
  for (long k = 0; k < 12; ++k)
  {
    const long half = 12 - k;
    for (long j = 20 - half; j < 20 + half; ++j)
      for (long i = 20 - half; i < 20 + half; ++i)
        setVoxel(mask.GetPointer(), i, j, k, 1);
  }
  const ContourStack stack = extractContours(mask);
  for (long k = 0; k < 12; ++k)
  {
    const double side = 2.0 * (12 - k);
    ASSERT_EQ(stack.slices[k].contours.size(), 1u) << "slice " << k;
    EXPECT_EQ(std::abs(signedArea(stack.slices[k].contours[0])), side * side - 0.5) << "slice " << k;
  }
}

TEST(ContourExtraction, DiagonalNeighboursAreSeparateContours)
{
  // Face connectivity at a saddle: voxels meeting only at a corner stay apart.
  auto mask = makeMask({ 6, 6, 1 });
  setVoxel(mask.GetPointer(), 2, 2, 0, 1);
  setVoxel(mask.GetPointer(), 3, 3, 0, 1);
  setVoxel(mask.GetPointer(), 1, 3, 0, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_EQ(stack.slices[0].contours.size(), 3u);
  expectSimpleAndSeparate(stack.slices[0]);
}

TEST(ContourExtraction, CheckerboardNeverSharesPoints)
{
  auto mask = makeMask({ 12, 12, 1 });
  for (long j = 1; j < 11; ++j)
    for (long i = 1; i < 11; ++i)
      if ((i + j) % 2 == 0 || (i > 4 && i < 8))
        setVoxel(mask.GetPointer(), i, j, 0, 1);
  const ContourStack stack = extractContours(mask);
  ASSERT_GT(stack.slices[0].contours.size(), 1u);
  expectSimpleAndSeparate(stack.slices[0]);
}

TEST(ContourExtraction, LargeMask)
{
  // 512 x 512 x 300 voxels, a disc of varying radius in most slices. The time is printed, not
  // asserted (speed is the benchmark's: README, "Limits").
  auto mask = makeMask({ 512, 512, 300 }, { 0.7, 0.7, 1.0 });
  unsigned char* voxel = mask->GetBufferPointer();
  for (long k = 0; k < 300; ++k)
  {
    const double radius = k < 20 || k >= 280 ? 0.0 : 60.0 + 100.0 * std::sin(k * M_PI / 300.0);
    for (long j = 0; j < 512; ++j)
      for (long i = 0; i < 512; ++i, ++voxel)
        *voxel = radius > 0.0 && (i - 256.0) * (i - 256.0) + (j - 250.0) * (j - 250.0) <= radius * radius;
  }
  const auto start = std::chrono::steady_clock::now();
  const ContourStack stack = extractContours(mask);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds", std::to_string(seconds));
  std::cout << "extractContours 512x512x300: " << seconds << " s\n";
  ASSERT_EQ(stack.slices.size(), 300u);
  EXPECT_TRUE(stack.slices[0].contours.empty());
  EXPECT_EQ(stack.slices[150].contours.size(), 1u);
}

TEST(ContourExtraction, SliceFrameCopiesTheImageGeometry)
{
  auto mask = makeMask({ 4, 4, 4 }, { 0.8, 0.5, 3.0 });
  MaskVolume::PointType origin;
  origin[0] = 10.0, origin[1] = -5.0, origin[2] = 2.0;
  mask->SetOrigin(origin);
  MaskVolume::DirectionType direction;
  direction.Fill(0.0);
  direction[0][1] = 1.0; // axis i points along y, axis j along -x
  direction[1][0] = -1.0;
  direction[2][2] = 1.0;
  mask->SetDirection(direction);
  const SliceFrame frame = sliceFrameOf(mask);
  EXPECT_EQ(frame.origin[0], 10.0);
  EXPECT_EQ(frame.origin[1], -5.0);
  EXPECT_EQ(frame.spacing[1], 0.5);
  EXPECT_EQ(frame.direction[0][1], 1.0);
  EXPECT_EQ(frame.direction[1][0], -1.0);

  // physical = origin + direction * (x, y, z) agrees with ITK for a stack point.
  MaskVolume::IndexType index = { { 1, 2, 3 } };
  itk::Point<double, 3> physical;
  mask->TransformIndexToPhysicalPoint(index, physical);
  const double local[3] = { 1 * 0.8, 2 * 0.5, 3 * 3.0 };
  for (int row = 0; row < 3; ++row)
  {
    double mapped = frame.origin[row];
    for (int column = 0; column < 3; ++column)
      mapped += frame.direction[row][column] * local[column];
    EXPECT_NEAR(mapped, physical[row], 1e-12);
  }
}

} // namespace
} // namespace slicemesh

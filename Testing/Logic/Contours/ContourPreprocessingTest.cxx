// Contour preprocessing: resampling to a point spacing, simplification within a tolerance, and
// that neither creates crossings.
#include "Contours/ContourCrossings.h"
#include "Contours/ContourPreparation.h"
#include "Meshing/MeshingOptions.h"
#include "Contours/ContourResampling.h"
#include "Contours/ContourSimplification.h"
#include "Contours/ContourSmoothing.h"
#include "Contours/MarchingSquares.h"
#include "Core/PlanarGeometry.h"

#include "ContourStacks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

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

/** The marching-squares contours of a binary image on a 1 mm grid: value -1 (inside) at the nodes
 *  where inside(x, y) holds, +1 elsewhere, traced at 0 (the midpoints of inside-outside edges, as
 *  the binary mask's 0.5 level): the voxel staircase. */
std::vector<Polygon2> staircaseContours(std::size_t nx, std::size_t ny, const std::function<bool(double, double)>& inside)
{
  ScalarGrid2 grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.values.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      grid.values[j * nx + i] = inside(static_cast<double>(i), static_cast<double>(j)) ? -1.0 : 1.0;
  return zeroContours(grid);
}

double polygonArea(const Polygon2& polygon)
{
  return 0.5 * twiceSignedArea(polygon);
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
  // A small contour keeps enough points for its shape, never more than it had; never under three.
  EXPECT_EQ(resampleContour(circle(0, 0, 0.1, 12), 5.0).size(), fewestResampledPoints);
  EXPECT_EQ(resampleContour(circle(0, 0, 0.1, 5), 5.0).size(), 5u);
  EXPECT_EQ(resampleContour(rectangle(0, 0, 0.1, 0.1), 5.0).size(), 4u);
  const Polygon2 two{ { 0, 0 }, { 1, 0 } };
  EXPECT_EQ(resampleContour(two, 5.0).size(), 3u);
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
  // A contour smaller than the tolerance keeps at least half its area: 4 of its points (a
  // triangle of 3 would keep 32% of the disk, the square 64%).
  const Polygon2 small = circle(0, 0, 0.2, 20);
  const Polygon2 kept = simplifyContours(std::vector<Polygon2>{ small }, 5.0).front();
  EXPECT_EQ(kept.size(), 4u);
  EXPECT_GE(polygonArea(kept), 0.5 * polygonArea(small));
}

TEST(ContourSimplification, AContourThinnerThanTheToleranceKeepsItsWidth)
{
  // A bar one pixel thick and six long on pixels of 1 x 0.5 mm, traced: every point lies within
  // 0.25 mm of the chord between its two ends, so at 0.3 mm Douglas-Peucker keeps a triangle of a
  // quarter of its area (a flat sliver the tiling cannot close).
  std::vector<Polygon2> bar = staircaseContours(12, 8, [](double x, double y) { return y == 3 && x >= 2 && x <= 7; });
  ASSERT_EQ(bar.size(), 1u);
  for (Point2& p : bar.front())
    p.y *= 0.5;
  for (double tolerance : { 0.2, 0.25, 0.3, 1.0, 10.0 })
  {
    const Polygon2 simplified = simplifyContours(bar, tolerance).front();
    SCOPED_TRACE(tolerance);
    EXPECT_GE(simplified.size(), 4u);
    EXPECT_LT(simplified.size(), bar.front().size());
    EXPECT_GE(polygonArea(simplified), 0.5 * polygonArea(bar.front()));
    EXPECT_TRUE(contourCrossings({ simplified }).empty());
  }
}

TEST(ContourSimplification, AKeptEdgeIsNoLongerThanTheBoundWherePointsAllow)
{
  // A bar one pixel thick and 1000 long, traced: a point on every pixel edge, the long sides each a
  // straight run. Collinear points alone dropped, it is four edges; with a bound of 8.8 mm every
  // kept edge is at most that, and no longer than needed by more than half.
  const std::vector<Polygon2> bar =
    staircaseContours(1004, 4, [](double x, double y) { return y == 1 && x >= 2 && x <= 1001; });
  ASSERT_EQ(bar.size(), 1u);
  const Polygon2 runEnds = simplifyContours(bar, 1e-3).front();
  EXPECT_LE(runEnds.size(), 8u);
  const double bound = 8.8;
  const Polygon2 bounded = simplifyContours(bar, 1e-3, bound).front();
  double longest = 0.0;
  for (std::size_t i = 0; i < bounded.size(); ++i)
    longest = std::max(longest, distance(bounded[i], bounded[(i + 1) % bounded.size()]));
  EXPECT_LE(longest, bound);
  EXPECT_LE(bounded.size(), 2u * static_cast<std::size_t>(2.0 * 1000.0 / bound) + 8u);
  EXPECT_NEAR(polygonArea(bounded), polygonArea(bar.front()), 1e-9);
  EXPECT_TRUE(contourCrossings({ bounded }).empty());
  for (const Point2& p : bounded)
    EXPECT_NE(std::find_if(bar.front().begin(), bar.front().end(), [&](const Point2& q) { return q.x == p.x && q.y == p.y; }),
              bar.front().end());
  // A bound does not hold points off the tolerance: a zigzag keeps the same points under a loose one.
  const Polygon2 zigzag = zigzagCircle(0, 0, 20, 0.25, 400);
  EXPECT_EQ(simplifyContours(std::vector<Polygon2>{ zigzag }, 1.0, 1000.0).front().size(),
            simplifyContours(std::vector<Polygon2>{ zigzag }, 1.0).front().size());
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

TEST(ContourSmoothing, StaircaseCircleComesCloserToTheTrueCircle)
{
  // A disk of radius 12.3 mm off the grid's nodes, traced on a 1 mm grid.
  const double cx = 20.37, cy = 19.21, r = 12.3;
  const std::vector<Polygon2> traced =
    staircaseContours(41, 41, [&](double x, double y) { return std::hypot(x - cx, y - cy) < r; });
  ASSERT_EQ(traced.size(), 1u);
  auto meanError = [&](const Polygon2& polygon) {
    double sum = 0.0;
    for (const Point2& p : polygon)
      sum += std::abs(std::hypot(p.x - cx, p.y - cy) - r);
    return sum / static_cast<double>(polygon.size());
  };
  ContourSmoothingOptions options;
  options.iterations = 30;
  options.maxDisplacement = 0.3;
  const Polygon2 smoothed = smoothContour(traced[0], options);
  ASSERT_EQ(smoothed.size(), traced[0].size());
  const double before = meanError(traced[0]), after = meanError(smoothed);
  std::printf("mean distance to the circle: traced %.4f mm, smoothed %.4f mm; area %.3f -> %.3f mm^2\n", before, after,
              polygonArea(traced[0]), polygonArea(smoothed));
  EXPECT_LT(after, 0.7 * before); // measured: 0.192 -> 0.122 mm
  // No point moves farther than the bound; the area is kept (restored after the filter).
  for (std::size_t i = 0; i < smoothed.size(); ++i)
    EXPECT_LE(distance(smoothed[i], traced[0][i]), 0.3 + 1e-12);
  EXPECT_NEAR(polygonArea(smoothed), polygonArea(traced[0]), 1e-3 * polygonArea(traced[0]));
  EXPECT_TRUE(contourCrossings({ smoothed }).empty());
}

TEST(ContourSmoothing, KeepsTheAreaOfSmallContoursAndTheOrientationOfHoles)
{
  ContourSmoothingOptions options;
  options.iterations = 30;
  options.maxDisplacement = 0.3;
  // A single voxel's contour (a diamond of 4 points) and a 2 x 1 voxel one: Taubin's filter alone
  // shrinks them (their shape is above the pass band); the area is restored.
  const Polygon2 voxel = { { 0.5, 0.0 }, { 1.0, 0.5 }, { 0.5, 1.0 }, { 0.0, 0.5 } };
  const Polygon2 pair = { { 0.5, 0.0 }, { 1.5, 0.0 }, { 2.0, 0.5 }, { 1.5, 1.0 }, { 0.5, 1.0 }, { 0.0, 0.5 } };
  for (const Polygon2& contour : { voxel, pair })
  {
    const Polygon2 smoothed = smoothContour(contour, options);
    std::printf("small contour area %.4f -> %.4f mm^2\n", polygonArea(contour), polygonArea(smoothed));
    EXPECT_NEAR(polygonArea(smoothed), polygonArea(contour), 0.02 * polygonArea(contour));
  }
  // A hole (clockwise) stays clockwise with its area.
  const Polygon2 hole = circle(0, 0, 5, 60, true);
  const Polygon2 smoothedHole = smoothContour(hole, options);
  EXPECT_LT(twiceSignedArea(smoothedHole), 0.0);
  EXPECT_NEAR(polygonArea(smoothedHole), polygonArea(hole), 1e-3 * std::abs(polygonArea(hole)));
  // Off, or fewer than 4 points: unchanged.
  options.iterations = 0;
  EXPECT_EQ(smoothContour(hole, options).front().x, hole.front().x);
  options.iterations = 30;
  const Polygon2 triangle = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  EXPECT_EQ(smoothContour(triangle, options)[1].x, 1.0);
}

TEST(ContourSmoothing, ContoursNeverCrossAfterSmoothing)
{
  // Random blobs on a 1 mm grid (voxels touching at corners, one-voxel gaps and necks, holes): the
  // contours of corner-touching voxels are 0.71 mm apart, so a bound of 0.3 mm alone keeps them
  // apart; at a bound of 1.5 mm only the safety net does.
  std::mt19937 random(4);
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<char> occupied(30 * 30);
    std::bernoulli_distribution coin(0.55);
    for (std::size_t j = 1; j + 1 < 30; ++j)
      for (std::size_t i = 1; i + 1 < 30; ++i)
        occupied[j * 30 + i] = coin(random);
    const std::vector<Polygon2> traced =
      staircaseContours(30, 30, [&](double x, double y) { return occupied[static_cast<std::size_t>(y) * 30 + static_cast<std::size_t>(x)] != 0; });
    ASSERT_TRUE(contourCrossings(traced).empty());
    for (double bound : { 0.3, 1.5 })
    {
      ContourSmoothingOptions options;
      options.iterations = 30;
      options.maxDisplacement = bound;
      const std::vector<Polygon2> smoothed = smoothContours(traced, options);
      ASSERT_EQ(smoothed.size(), traced.size());
      EXPECT_TRUE(contourCrossings(smoothed).empty()) << "trial " << trial << ", bound " << bound;
      for (std::size_t c = 0; c < traced.size(); ++c)
      {
        ASSERT_EQ(smoothed[c].size(), traced[c].size());
        for (std::size_t i = 0; i < traced[c].size(); ++i)
          EXPECT_LE(distance(smoothed[c][i], traced[c][i]), bound + 1e-12);
        EXPECT_EQ(twiceSignedArea(smoothed[c]) > 0.0, twiceSignedArea(traced[c]) > 0.0);

      }
    }
  }

}

TEST(ContourSmoothing, SafetyNetPutsBackContoursThatWouldCross)
{
  // A block with a notch 3 voxels wide and an island one voxel wide in the notch, 1 voxel from its
  // walls: strong smoothing with a loose bound closes the notch onto the island; the net keeps
  // the block as traced.
  auto inside = [](double x, double y) {
    const bool block = x >= 2 && x <= 17 && y >= 2 && y <= 17 && !(x >= 8 && x <= 10 && y >= 10);
    const bool island = x == 9 && y >= 12 && y <= 16;
    return block || island;
  };
  const std::vector<Polygon2> traced = staircaseContours(20, 20, inside);
  ASSERT_EQ(traced.size(), 2u);
  ASSERT_TRUE(contourCrossings(traced).empty());
  ContourSmoothingOptions options;
  options.iterations = 300;
  options.mu = 0.0; // no inflation: plain Laplacian smoothing, which fills the notch
  options.maxDisplacement = 3.0;
  std::vector<Polygon2> alone;
  for (const Polygon2& contour : traced)
    alone.push_back(smoothContour(contour, options));
  ASSERT_FALSE(contourCrossings(alone).empty()); // what the net is for
  const std::vector<Polygon2> smoothed = smoothContours(traced, options);
  EXPECT_TRUE(contourCrossings(smoothed).empty());
  // A stack keeps its slices, empty ones included.
  const ContourStack stack{ { { 0.0, traced }, { 1.0, {} } }, 1.0 };
  const ContourStack out = smoothContours(stack, options);
  ASSERT_EQ(out.slices.size(), 2u);
  EXPECT_EQ(out.slices[0].contours.size(), 2u);
  EXPECT_TRUE(out.slices[1].contours.empty());
}

TEST(ContourResampling, KeepingTheAreaUndoesTheChordsCut)
{
  // A 6 x 6 voxel square as traced (chamfered corners) resampled at 1.41 mm: the chords cut the
  // corners (measured about 2% of the area); kept, the area is the input's.
  const std::vector<Polygon2> square =
    staircaseContours(12, 12, [](double x, double y) { return x >= 3 && x <= 8 && y >= 3 && y <= 8; });
  ASSERT_EQ(square.size(), 1u);
  const double area = polygonArea(square[0]);
  const Polygon2 cut = resampleContour(square[0], 1.41);
  const Polygon2 kept = resampleContourKeepingArea(square[0], 1.41);
  std::printf("square area %.3f, resampled %.3f, keeping the area %.3f mm^2\n", area, polygonArea(cut), polygonArea(kept));
  EXPECT_LT(polygonArea(cut), 0.99 * area);
  EXPECT_NEAR(polygonArea(kept), area, 1e-6 * area);
  EXPECT_EQ(kept.size(), cut.size());
  // On a circle the points move out by about a third of the sagitta (chord^2 / 8r).
  const Polygon2 fine = circle(0, 0, 10, 2000);
  const Polygon2 coarse = resampleContourKeepingArea(fine, 2.0);
  EXPECT_NEAR(polygonArea(coarse), polygonArea(fine), 1e-6 * polygonArea(fine));
  for (const Point2& p : coarse)
    EXPECT_LT(std::abs(std::hypot(p.x, p.y) - 10.0), 2.0 * 2.0 / (8.0 * 10.0));
  // Through the slice version: crossing-free as before.
  const std::vector<Polygon2> ring = { circle(0, 0, 10, 400), circle(0, 0, 9.7, 400, true) };
  EXPECT_TRUE(contourCrossings(resampleContours(ring, 8.0, ResampledShape::KeepingArea)).empty());
}

TEST(ContourResampling, KeepingTheCornersKeepsASquareAndASlot)
{
  // A drawn 40 x 40 square with points at irregular steps along its sides, and a 2 mm slot cut 20 mm
  // into it: resampled at 2.5 mm, every corner is a point of the result and every point lies on the
  // drawn polyline, so the area is the drawn one. Without the corners the chords cut them.
  auto onPolyline = [](const Point2& p, const Polygon2& polyline)
  {
    double nearest = 1e9;
    for (std::size_t i = 0; i < polyline.size(); ++i)
      nearest = std::min(nearest, distanceToSegment(p, polyline[i], polyline[(i + 1) % polyline.size()]));
    return nearest;
  };
  const Polygon2 square = { { -20, -20 }, { -7.3, -20 }, { 20, -20 }, { 20, 3.1 }, { 20, 20 },
                            { 11.9, 20 }, { -20, 20 }, { -20, -4.4 } };
  const Polygon2 slot = { { -20, -20 }, { 20, -20 }, { 20, -1 }, { 0, -1 }, { 0, 1 }, { 20, 1 }, { 20, 20 }, { -20, 20 } };
  const Polygon2 squareCorners = { { -20, -20 }, { 20, -20 }, { 20, 20 }, { -20, 20 } };
  for (const auto& [drawn, corners] : { std::pair{ square, squareCorners }, std::pair{ slot, slot } })
  {
    const Polygon2 resampled = resampleContourKeepingCorners(drawn, 2.5);
    for (const Point2& corner : corners)
      EXPECT_TRUE(std::any_of(resampled.begin(), resampled.end(),
                              [&](const Point2& p) { return p.x == corner.x && p.y == corner.y; }))
        << "corner " << corner.x << ", " << corner.y << " lost";
    for (const Point2& p : resampled)
      EXPECT_LT(onPolyline(p, drawn), 1e-9);
    EXPECT_NEAR(polygonArea(resampled), polygonArea(drawn), 1e-9);
    for (std::size_t i = 0; i < resampled.size(); ++i) // even steps between the corners
      EXPECT_LT(distance(resampled[i], resampled[(i + 1) % resampled.size()]), 1.5 * 2.5);
  }
  EXPECT_EQ(contourCorners(slot, 2.5).size(), 8u);
  EXPECT_LT(polygonArea(resampleContour(square, 2.5 * 1.3)), polygonArea(square) - 1.0); // chords cut corners
  // A circle drawn with 64 points turns by 5.6 degrees at each: no corners, evenly resampled.
  EXPECT_TRUE(contourCorners(circle(0, 0, 10, 64), 2.5).empty());
  EXPECT_EQ(resampleContourKeepingCorners(circle(0, 0, 10, 64), 2.5).size(), 25u);
}

TEST(ContourPreparation, TracedContoursLoseOnlyThePointsOnAStraightRun)
{
  // A disc of radius 12 voxels and a 10 x 6 block, traced on 0.7 mm pixels: the default preparation
  // of a remeshed surface's traced contours keeps every point where the staircase turns and drops
  // those in between on a straight run (along a voxel wall or a 45-degree chamfer). The polygons are the same: every
  // traced point lies on the prepared contour, and the areas agree to rounding.
  ContourStack stack;
  stack.sliceSpacing = 0.7;
  Slice slice;
  const double pixel = 0.7;
  for (Polygon2 contour :
       { staircaseContours(40, 40, [](double x, double y) { return (x - 20) * (x - 20) + (y - 20) * (y - 20) <= 144.0; })
           .front(),
         staircaseContours(20, 12, [](double x, double y) { return x >= 4 && x <= 13 && y >= 3 && y <= 8; }).front() })
  {
    for (Point2& p : contour)
      p = { p.x * pixel, p.y * pixel };
    slice.contours.push_back(contour);
  }
  stack.slices = { slice };
  const ContourPreparationOptions resolved = resolvedMeshingOptions({}, { pixel, pixel, 0.7 }).contours;
  ASSERT_EQ(resolved.mode, ContourPreparation::Traced);
  EXPECT_NEAR(resolved.simplificationTolerance, 1e-3 * pixel, 1e-12);
  const ContourStack prepared = prepareContours(stack, resolved);
  ASSERT_EQ(prepared.slices.size(), 1u);
  ASSERT_EQ(prepared.slices[0].contours.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c)
  {
    const Polygon2& traced = stack.slices[0].contours[c];
    const Polygon2& kept = prepared.slices[0].contours[c];
    std::printf("contour %zu: %zu traced points, %zu kept\n", c, traced.size(), kept.size());
    EXPECT_LT(kept.size(), traced.size());
    for (const Point2& p : traced)
      EXPECT_LT(distanceToPolygon(p, kept), 1e-9);
    EXPECT_NEAR(polygonArea(kept), polygonArea(traced), 1e-9 * std::abs(polygonArea(traced)));
    // Only points on straight runs go: the staircase's turns are kept, and at most the three anchors
    // the simplification splits a closed contour at besides.
    std::size_t turns = 0;
    for (std::size_t i = 0; i < traced.size(); ++i)
    {
      const Point2& a = traced[(i + traced.size() - 1) % traced.size()];
      const Point2& b = traced[i];
      const Point2& d = traced[(i + 1) % traced.size()];
      turns += std::abs((b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x)) > 1e-9;
    }
    EXPECT_LE(kept.size(), turns + 3);
    EXPECT_GE(kept.size(), turns);
  }
  // The block's contour is its four sides with a chamfer at each corner: eight points, and the
  // middle of each long side (6.3 mm, longer than the bound of eight 0.77 mm target edges).
  EXPECT_EQ(prepared.slices[0].contours[1].size(), 10u);
  EXPECT_NEAR(resolved.simplificationMaxEdge, simplifiedEdgeBound * automaticEdgeLength({ pixel, pixel, 0.7 }), 1e-12);
}

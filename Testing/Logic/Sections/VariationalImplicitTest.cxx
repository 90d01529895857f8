#include "Sections/ContourConstraints.h"
#include "ContourStacks.h"
#include "Contours/MarchingSquares.h"
#include "Sections/VariationalImplicit.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** Three slices of a sphere of radius 10 at the origin. */
std::vector<Slice> sphereSlices(int points)
{
  std::vector<Slice> slices;
  for (double z : { -5.0, 0.0, 5.0 })
    slices.push_back({ z, { circle(0, 0, std::sqrt(100.0 - z * z), points) } });
  return slices;
}

double seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

TEST(VariationalImplicit, InterpolatesItsConstraints)
{
  std::vector<ImplicitConstraint> constraints;
  ConstraintSummary summary;
  constraints = contourConstraints(sphereSlices(120), {}, &summary);
  EXPECT_LE(constraints.size(), 600u);
  EXPECT_GT(summary.offSurface, 0u);
  VariationalImplicitFunction f;
  f.fit(constraints);
  EXPECT_LT(f.residual(), 1e-8);
  for (const ImplicitConstraint& c : constraints)
    EXPECT_NEAR(f(c.position), c.value, 1e-7);
}

TEST(VariationalImplicit, SignIsNegativeInside)
{
  VariationalImplicitFunction f;
  f.fit(contourConstraints(sphereSlices(120)));
  EXPECT_LT(f({ 0, 0, 0 }), 0.0);
  EXPECT_LT(f({ 5, 0, 2.5 }), 0.0);
  EXPECT_GT(f({ 12, 0, 0 }), 0.0);
  EXPECT_GT(f({ 0, -11, 2.5 }), 0.0);
  // Between the slices the zero level lies near the sphere (radius at z = 2.5 is 9.68).
  const double r = std::sqrt(100.0 - 2.5 * 2.5);
  EXPECT_LT(f({ r - 0.3, 0, 2.5 }), 0.0);
  EXPECT_GT(f({ r + 0.3, 0, 2.5 }), 0.0);
}

TEST(VariationalImplicit, HoleNormalsPointIntoTheHole)
{
  // An annulus: the solid is between radius 4 and 10, the hole is outside the solid.
  std::vector<Slice> slices;
  for (double z : { 0.0, 3.0 })
    slices.push_back({ z, { circle(0, 0, 10, 80), circle(0, 0, 4, 40) } });
  VariationalImplicitFunction f;
  f.fit(contourConstraints(slices));
  EXPECT_GT(f({ 0, 0, 1.5 }), 0.0); // in the hole
  EXPECT_LT(f({ 7, 0, 1.5 }), 0.0); // in the solid
  EXPECT_GT(f({ 12, 0, 1.5 }), 0.0);
}

TEST(VariationalImplicit, CoplanarCentresAreRejected)
{
  VariationalImplicitFunction f;
  std::vector<Slice> one{ { 0.0, { circle(0, 0, 5, 40) } } };
  EXPECT_THROW(f.fit(contourConstraints(one)), Error);
  EXPECT_THROW(f.fit({ { { 0, 0, 0 }, 0 }, { { 1, 0, 0 }, 0 } }), Error);
}

TEST(VariationalImplicit, SolveTimeForLargeContours)
{
  // Two slices of 3000-point contours: the constraints are subsampled to the centre budget, so the
  // dense solve stays O(budget^3) whatever the contours' size. Measured and printed, not asserted.
  std::vector<Slice> slices{ { 0.0, { circle(0, 0, 40, 3000) } }, { 3.0, { circle(2, 1, 38, 3000) } } };
  for (std::size_t budget : { 300u, 600u, 1200u, 2000u })
  {
    ConstraintSampling sampling;
    sampling.maxCentres = budget;
    auto start = std::chrono::steady_clock::now();
    const std::vector<ImplicitConstraint> constraints = contourConstraints(slices, sampling);
    const double sampleTime = seconds(start);
    start = std::chrono::steady_clock::now();
    VariationalImplicitFunction f;
    f.fit(constraints);
    const double fitTime = seconds(start);
    std::cout << "[ timing   ] RBF, 2 x 3000-point contours, budget " << budget << ": " << f.centres()
              << " centres, constraints " << sampleTime * 1e3 << " ms, solve " << fitTime * 1e3 << " ms, residual "
              << f.residual() << "\n";
    EXPECT_LE(f.centres(), budget + 16);
    EXPECT_LT(f({ 0, 0, 1.5 }), 0.0);
  }
}

TEST(VariationalImplicit, ManySmallContoursStayNearTheBudget)
{
  // A spray of small contours (noise): eight samples each would be far over the budget, and the
  // dense solve grows with the cube of the centres. Each gets three; too many are refused.
  auto spray = [](int perSide) {
    std::vector<Slice> slices;
    for (double z : { 0.0, 2.0 })
    {
      Slice slice{ z, {} };
      for (int i = 0; i < perSide; ++i)
        for (int j = 0; j < perSide; ++j)
          slice.contours.push_back(circle(3.0 * i, 3.0 * j, 1.0, 12));
      slices.push_back(slice);
    }
    return slices;
  };
  const ConstraintSampling sampling; // 600 centres
  const std::vector<ImplicitConstraint> constraints = contourConstraints(spray(7), sampling); // 98 contours
  EXPECT_LE(constraints.size(), 3 * 98 * 3 + sampling.maxCentres);
  EXPECT_GT(constraints.size(), sampling.maxCentres / 2);
  EXPECT_THROW(contourConstraints(spray(11), sampling), Error); // 242 contours
}

TEST(MarchingSquares, CircleBecomesOneCounterClockwiseLoop)
{
  const double r = 7.3;
  const ScalarGrid2 grid = sampleGrid({ -10, -10, 10, 10 }, 0.5, [&](const std::vector<Point2>& p, std::vector<double>& v) {
    v.clear();
    for (const Point2& q : p)
      v.push_back(std::hypot(q.x - 0.2, q.y) - r);
  });
  const std::vector<Polygon2> loops = zeroContours(grid);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_GT(twiceSignedArea(loops[0]), 0.0);
  EXPECT_NEAR(0.5 * twiceSignedArea(loops[0]), M_PI * r * r, 0.01 * M_PI * r * r);
  for (const Point2& p : loops[0])
    EXPECT_NEAR(std::hypot(p.x - 0.2, p.y), r, 0.05);
}

TEST(MarchingSquares, AnnulusGivesAClockwiseHoleAndBorderClosesContours)
{
  const ScalarGrid2 grid = sampleGrid({ -10, -10, 10, 10 }, 0.5, [](const std::vector<Point2>& p, std::vector<double>& v) {
    v.clear();
    for (const Point2& q : p)
    {
      const double d = std::hypot(q.x, q.y);
      v.push_back(std::max(d - 8.0, 3.0 - d)); // solid between radius 3 and 8
    }
  });
  std::vector<Polygon2> loops = zeroContours(grid);
  ASSERT_EQ(loops.size(), 2u);
  int ccw = 0, cw = 0;
  for (const Polygon2& loop : loops)
    (twiceSignedArea(loop) > 0 ? ccw : cw)++;
  EXPECT_EQ(ccw, 1);
  EXPECT_EQ(cw, 1);

  // A field negative everywhere still closes, along the grid's border.
  const ScalarGrid2 full = sampleGrid({ 0, 0, 4, 4 }, 1.0, [](const std::vector<Point2>& p, std::vector<double>& v) {
    v.assign(p.size(), -1.0);
  });
  loops = zeroContours(full);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_GT(twiceSignedArea(loops[0]), 0.0);
}

TEST(MarchingSquares, SaddleRuleIsConsistent)
{
  // A checkerboard of values: every interior cell is a saddle; the loops must still close and the
  // mean rule must decide: negative mean joins the negative corners into one region.
  for (double bias : { -0.2, 0.2 })
  {
    const ScalarGrid2 grid = sampleGrid({ 0, 0, 6, 6 }, 1.0, [&](const std::vector<Point2>& p, std::vector<double>& v) {
      v.clear();
      for (const Point2& q : p)
        v.push_back(((static_cast<int>(q.x) + static_cast<int>(q.y)) % 2 == 0 ? -1.0 : 1.0) + bias);
    });
    const std::vector<Polygon2> loops = zeroContours(grid);
    ASSERT_FALSE(loops.empty());
    std::size_t holes = 0;
    for (const Polygon2& loop : loops)
      holes += twiceSignedArea(loop) < 0 ? 1 : 0;
    if (bias < 0)
      EXPECT_GT(holes, 0u) << "joined negative corners leave positive islands as holes";
    else
      EXPECT_EQ(holes, 0u) << "separate negative corners are separate outer loops";
  }
}

// The angles of a triangle (TriangleAngles.h), the one measure of them the stages share.
#include "Measures/TriangleAngles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace slicemesh;

namespace
{
double degrees(double radians)
{
  return radians * 180.0 / M_PI;
}
} // namespace

TEST(TriangleAngles, RightEquilateralAndSliverTrianglesInSpace)
{
  // A 3-4-5 right triangle tilted out of every coordinate plane: angles 90, atan(4/3), atan(3/4) at the
  // corners opposite the hypotenuse, the side 4 and the side 3.
  const Point3 o{ 1, 2, 3 };
  const double h = std::sqrt(2.0) / 2;
  const Point3 a{ o.x + 3 * h, o.y + 3 * h, o.z };             // o + 3 (1, 1, 0) / sqrt 2
  const Point3 b{ o.x - 4 * 0.5, o.y + 4 * 0.5, o.z + 4 * h }; // o + 4 (-1, 1, sqrt 2) / 2, orthogonal
  const std::array<double, 3> angles = triangleAngles(o, a, b);
  EXPECT_NEAR(degrees(angles[0]), 90.0, 1e-12);
  EXPECT_NEAR(degrees(angles[1]), degrees(std::atan2(4.0, 3.0)), 1e-12);
  EXPECT_NEAR(degrees(angles[2]), degrees(std::atan2(3.0, 4.0)), 1e-12);
  EXPECT_NEAR(degrees(angles[0] + angles[1] + angles[2]), 180.0, 1e-12);
  EXPECT_NEAR(degrees(smallestAngle(o, a, b)), degrees(std::atan2(3.0, 4.0)), 1e-12);
  EXPECT_NEAR(smallestAngleCosine(o, a, b), 0.8, 1e-14); // cos(atan(3/4)) = 4/5

  const Point3 p{ 0, 0, 0 }, q{ 1, 0, 0 }, r{ 0.5, std::sqrt(3.0) / 2, 0 };
  for (double angle : triangleAngles(p, q, r))
    EXPECT_NEAR(degrees(angle), 60.0, 1e-12);
  EXPECT_NEAR(smallestAngleCosine(p, q, r), 0.5, 1e-14);

  // A sliver 1e-7 high over a base of 2: its smallest angles are 1e-7 rad, still to full precision,
  // where an arc cosine of its cosine would have lost half the digits.
  const Point3 u{ -1, 0, 0 }, v{ 1, 0, 0 }, w{ 0, 1e-7, 0 };
  EXPECT_NEAR(smallestAngle(u, v, w) / std::atan(1e-7), 1.0, 1e-12);
  EXPECT_NEAR(degrees(triangleAngles(u, v, w)[2]), 180.0 - degrees(2.0 * std::atan(1e-7)), 1e-9);
}

TEST(TriangleAngles, TheSmallestAngleIsTheOneOppositeTheShortestEdge)
{
  // smallestAngle measures only that corner: the same as the least of the three, to rounding, on
  // triangles of every shape (slivers, needles, nearly equilateral ones) in random position.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0), squash(1e-6, 1.0);
  for (int n = 0; n < 20000; ++n)
  {
    const Point3 a{ coordinate(random), coordinate(random), coordinate(random) };
    Point3 b{ coordinate(random), coordinate(random), coordinate(random) };
    Point3 c{ coordinate(random), coordinate(random), coordinate(random) };
    if (n % 2 == 1) // c pulled towards ab's midpoint: a flat triangle
    {
      const double t = squash(random);
      c = { 0.5 * (a.x + b.x) + t * (c.x - 0.5 * (a.x + b.x)), 0.5 * (a.y + b.y) + t * (c.y - 0.5 * (a.y + b.y)),
            0.5 * (a.z + b.z) + t * (c.z - 0.5 * (a.z + b.z)) };
    }
    const std::array<double, 3> angles = triangleAngles(a, b, c);
    const double least = std::min({ angles[0], angles[1], angles[2] });
    EXPECT_NEAR(smallestAngle(a, b, c), least, 1e-13 * std::max(1.0, least)) << n;
  }
}

TEST(TriangleAngles, DegenerateTriangles)
{
  const Point3 a{ 0, 0, 0 }, b{ 2, 0, 0 }, c{ 1, 0, 0 };
  // Three points on a line: no area, angles 0, 0 and 180 degrees, a cosine of 1 (an angle of 0).
  EXPECT_EQ(smallestAngle(a, b, c), 0.0);
  EXPECT_NEAR(degrees(triangleAngles(a, b, c)[2]), 180.0, 1e-12);
  EXPECT_EQ(smallestAngleCosine(a, b, c), 1.0);
  // Two corners in one place.
  EXPECT_EQ(smallestAngle(a, a, b), 0.0);
  EXPECT_EQ(smallestAngleCosine(a, a, b), 1.0);
}

TEST(TriangleAngles, AnAngleThatIsTheBoundIsNotUnderIt)
{
  // 30 degrees exactly at o, between (1, 0.5, 0.5) and (0.5, 0.5, 0), as half-voxel coordinates on an
  // isotropic grid give them; its computed value may fall a bit either side of 30.
  const Point3 o{ 10, 20, 30 }, p{ 11, 20.5, 30.5 }, q{ 10.5, 20.5, 30 };
  const double angle = triangleAngles(o, p, q)[0];
  EXPECT_NEAR(degrees(angle), 30.0, 1e-12);
  EXPECT_FALSE(angleUnder(angle, 30.0));
  EXPECT_TRUE(angleUnder(angle, 30.001));
  EXPECT_TRUE(angleUnder(29.999 * M_PI / 180.0, 30.0));
  EXPECT_FALSE(angleUnder(30.001 * M_PI / 180.0, 30.0));
}

TEST(TriangleAngles, ASmallestAngleBoundAnswersAsTheAngleDoes)
{
  // Random triangles, and isosceles ones whose apex angle, their smallest, is the bound itself or
  // a few ulps to a millionth of a degree off it (where the cosine cannot decide), plus slivers
  // and a triangle without area: metBy agrees with comparing smallestAngle every time.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  for (double boundDegrees : { 10.0, 20.0, 30.0 })
  {
    const double bound = boundDegrees * M_PI / 180.0;
    const SmallestAngleBound good(bound);
    std::size_t met = 0, checked = 0;
    auto check = [&](const Point3& a, const Point3& b, const Point3& c)
    {
      const bool expected = smallestAngle(a, b, c) >= bound;
      EXPECT_EQ(good.metBy(a, b, c), expected) << degrees(smallestAngle(a, b, c));
      met += expected;
      ++checked;
    };
    for (int i = 0; i < 20000; ++i)
      check({ coordinate(random), coordinate(random), coordinate(random) },
            { coordinate(random), coordinate(random), coordinate(random) },
            { coordinate(random), coordinate(random), coordinate(random) });
    for (double off : { 0.0, 1e-15, -1e-15, 1e-12, -1e-12, 1e-9, -1e-9, 1e-8, -1e-8 })
    {
      const double apex = bound + off, legs = 3.0;
      const Point3 o{ 0.5, -1.0, 2.0 };
      check(o, { o.x + legs, o.y, o.z }, { o.x + legs * std::cos(apex), o.y + legs * std::sin(apex), o.z });
    }
    check({ 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1e-9, 0 });
    check({ 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 });
    EXPECT_GT(met, 0u);
    EXPECT_LT(met, checked);
  }
}

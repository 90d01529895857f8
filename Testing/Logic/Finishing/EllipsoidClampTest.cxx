// The smoothing bound's clamp: a displacement outside the ellipsoid goes to the ellipsoid's nearest
// point, in double and in single precision; on equal axes that is the displacement scaled onto it.
#include "Finishing/EllipsoidClamp.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slicemesh;

namespace
{

constexpr double pi = 3.14159265358979323846;

/** f * d for the clamp's factors, and the squared distance from d. */
struct Clamped
{
  std::array<double, 3> point;
  double squaredDistance;
};

template <typename Real>
Clamped clamp(const std::array<double, 3>& d, const std::array<double, 3>& semiAxes)
{
  const std::array<Real, 3> u{ Real(d[0] / semiAxes[0]), Real(d[1] / semiAxes[1]), Real(d[2] / semiAxes[2]) };
  const std::array<Real, 3> w{ Real(1 / (semiAxes[0] * semiAxes[0])), Real(1 / (semiAxes[1] * semiAxes[1])),
                               Real(1 / (semiAxes[2] * semiAxes[2])) };
  const std::array<Real, 3> f = nearestOnEllipsoidFactors<Real>(u, w);
  Clamped c{ {}, 0.0 };
  for (int i = 0; i < 3; ++i)
  {
    c.point[i] = static_cast<double>(f[i]) * d[i];
    c.squaredDistance += (c.point[i] - d[i]) * (c.point[i] - d[i]);
  }
  return c;
}

double reachSquared(const std::array<double, 3>& p, const std::array<double, 3>& semiAxes)
{
  double r = 0.0;
  for (int i = 0; i < 3; ++i)
    r += (p[i] / semiAxes[i]) * (p[i] / semiAxes[i]);
  return r;
}

/** The smallest squared distance from d to points of the ellipsoid, by sampling it densely. */
double sampledSquaredDistance(const std::array<double, 3>& d, const std::array<double, 3>& a)
{
  double best = 1e300;
  const int steps = 720;
  for (int i = 0; i <= steps; ++i)
  {
    const double polar = pi * i / steps;
    for (int j = 0; j < 2 * steps; ++j)
    {
      const double azimuth = pi * j / steps;
      const std::array<double, 3> p{ a[0] * std::sin(polar) * std::cos(azimuth),
                                     a[1] * std::sin(polar) * std::sin(azimuth), a[2] * std::cos(polar) };
      const double dx = p[0] - d[0], dy = p[1] - d[1], dz = p[2] - d[2];
      best = std::min(best, dx * dx + dy * dy + dz * dz);
    }
  }
  return best;
}

} // namespace

TEST(EllipsoidClamp, TakesADisplacementOutsideToTheNearestPointOfTheEllipsoid)
{
  // The bound of a grid whose slices are half its pixels (0.3 of 1, 1, 0.5 mm), and a long thin one.
  const std::array<double, 3> flat{ 0.3, 0.3, 0.15 }, thin{ 0.9, 0.24, 0.24 };
  const std::array<std::array<double, 3>, 6> moves{ { { 0.35, 0.05, 0.22 },
                                                      { -0.2, 0.3, -0.3 },
                                                      { 0.01, -0.02, 0.4 },
                                                      { 1.5, 0.1, -0.2 },
                                                      { -0.3, -0.3, 0.3 },
                                                      { 0.0, 2.0, 0.0 } } };
  for (const auto& axes : { flat, thin })
    for (const auto& d : moves)
    {
      ASSERT_GT(reachSquared(d, axes), 1.0);
      const Clamped c = clamp<double>(d, axes);
      EXPECT_LE(reachSquared(c.point, axes), 1.0 + 1e-12);
      EXPECT_NEAR(reachSquared(c.point, axes), 1.0, 1e-6); // on it, not inside
      // No sampled point of the ellipsoid is nearer (the samples are about 0.002 mm apart).
      EXPECT_LE(std::sqrt(c.squaredDistance), std::sqrt(sampledSquaredDistance(d, axes)) + 1e-6);
      // The shortened move: nearer than the displacement scaled onto the ellipsoid, where the axes differ.
      const double scale = 1.0 / std::sqrt(reachSquared(d, axes));
      double scaledSquared = 0.0;
      for (int i = 0; i < 3; ++i)
        scaledSquared += (scale * d[i] - d[i]) * (scale * d[i] - d[i]);
      EXPECT_LE(c.squaredDistance, scaledSquared + 1e-12);
      // Single precision lands within a micrometre of it, still on or inside.
      const Clamped single = clamp<float>(d, axes);
      EXPECT_LE(reachSquared(single.point, axes), 1.0 + 1e-5);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(single.point[i], c.point[i], 1e-3 * 1e-3 * 1e3); // 1 um
    }
}

TEST(EllipsoidClamp, KeepsTheMoveAcrossAWallAndCutsTheDriftAlongIt)
{
  // A vertex on a wall across thin slices (normal along x) moves 0.25 mm across it and drifts 0.2 mm
  // along z. Scaled onto the ellipsoid the whole move shrinks, to 0.16 mm across; the nearest point
  // keeps 0.21 mm across, and less of the drift.
  const std::array<double, 3> axes{ 0.3, 0.3, 0.15 };
  const std::array<double, 3> d{ 0.25, 0.0, 0.2 };
  const Clamped c = clamp<double>(d, axes);
  const double scale = 1.0 / std::sqrt(reachSquared(d, axes));
  EXPECT_NEAR(scale * d[0], 0.159, 0.001);
  EXPECT_NEAR(c.point[0], 0.207, 0.001);
  EXPECT_LT(c.point[2], scale * d[2]);
}

TEST(EllipsoidClamp, OnEqualAxesIsTheDisplacementScaledOntoTheSphere)
{
  const std::array<double, 3> axes{ 0.3, 0.3, 0.3 };
  const std::array<double, 3> d{ 0.4, -0.1, 0.25 };
  const Clamped c = clamp<double>(d, axes);
  const double scale = 1.0 / std::sqrt(reachSquared(d, axes));
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(c.point[i], scale * d[i], 1e-12);
}

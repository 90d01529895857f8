// Hand-made contour stacks for the Logic tests: analytic shapes sliced exactly.
#ifndef ContourStacks_h
#define ContourStacks_h

#include "Core/SliceMeshTypes.h"

#include <cmath>
#include <functional>
#include <random>

namespace slicemesh::testing
{

/** A random star-shaped contour of n points around (cx, cy): radius modulated by random second and
 *  third harmonics of up to a quarter of it, so neighbouring slices cross each other everywhere. */
inline Polygon2 randomStar(std::mt19937& rng, double cx, double cy, double radius, int n, bool clockwise)
{
  std::uniform_real_distribution<double> amplitude(0.0, 0.25), phase(0.0, 2 * M_PI);
  const double a2 = amplitude(rng), a3 = amplitude(rng), p2 = phase(rng), p3 = phase(rng), p0 = phase(rng);
  Polygon2 polygon;
  for (int i = 0; i < n; ++i)
  {
    const double t = p0 + 2 * M_PI * i / n * (clockwise ? -1 : 1);
    const double r = radius * (1.0 + a2 * std::sin(2 * t + p2) + a3 * std::sin(3 * t + p3));
    polygon.push_back({ cx + r * std::cos(t), cy + r * std::sin(t) });
  }
  return polygon;
}

/** A random star (as randomStar) of `points` points around (shift, shift), the three drawn from
 *  rng one by one (count, y, x) rather than as a call's arguments, whose order of evaluation is the
 *  compiler's choice (GCC and clang differ): the stacks must not depend on the compiler. */
inline Polygon2 randomShiftedStar(std::mt19937& rng, std::uniform_real_distribution<double>& shift,
                                  std::uniform_int_distribution<int>& points, double radius, bool clockwise)
{
  const int n = points(rng);
  const double cy = shift(rng);
  const double cx = shift(rng);
  return randomStar(rng, cx, cy, radius, n, clockwise);
}

/** A circle of n points, counter-clockwise unless reversed. */
inline Polygon2 circle(double cx, double cy, double r, int n, bool clockwise = false, double phase = 0.0)
{
  Polygon2 polygon;
  for (int i = 0; i < n; ++i)
  {
    const double a = phase + 2.0 * M_PI * i / n * (clockwise ? -1.0 : 1.0);
    polygon.push_back({ cx + r * std::cos(a), cy + r * std::sin(a) });
  }
  return polygon;
}

inline Polygon2 rectangle(double x0, double y0, double x1, double y1)
{
  return { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } };
}

/** Slices z = z0, z0 + dz, ... up to z1, each filled by contoursAt(z). */
inline ContourStack sliceStack(double z0, double z1, double dz, const std::function<std::vector<Polygon2>(double)>& contoursAt)
{
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (double z = z0; z <= z1 + 1e-9; z += dz)
    stack.slices.push_back({ z, contoursAt(z) });
  return stack;
}

/** A ball of radius r about (cx, cy, cz) as circles of n points on slices dz apart, the first half a
 *  slice above its lowest point. */
inline ContourStack ballStack(double cx, double cy, double cz, double r, int n, double dz)
{
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (double z = -r + dz / 2.0; z < r; z += dz)
    stack.slices.push_back({ cz + z, { circle(cx, cy, std::sqrt(r * r - z * z), n) } });
  return stack;
}

/** Distance from p to a sphere's surface. */
inline double sphereDistance(const Point3& p, const Point3& c, double r)
{
  return std::abs(std::sqrt((p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y) + (p.z - c.z) * (p.z - c.z)) - r);
}

} // namespace slicemesh::testing

#endif

#include "Measures/PointsInside.h"

#include "Core/ParallelFor.h"
#include "Core/SpatialHash.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace slicemesh
{
namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/** The sign of the 2D orientation of (a, b, c) in the coordinates (u, v). */
int orientation2(double au, double av, double bu, double bv, double cu, double cv)
{
  return static_cast<int>(CGAL::orientation(Kernel::Point_2(au, av), Kernel::Point_2(bu, bv), Kernel::Point_2(cu, cv)));
}

/** The side of the plan edge a -> b on which the moved point p + (e, e^2) lies: the orientation of
 *  (a, b, p), or where it is 0 the leading term of the perturbation (e: a.y - b.y; e^2: b.x - a.x).
 *  0 only for an edge that is a point in plan. */
int sideOfEdge(const Point3& a, const Point3& b, const Point3& p)
{
  const int side = orientation2(a.x, a.y, b.x, b.y, p.x, p.y);
  if (side != 0)
    return side;
  if (a.y != b.y)
    return a.y > b.y ? 1 : -1;
  if (a.x != b.x)
    return b.x > a.x ? 1 : -1;
  return 0;
}

/** The side of the plane of (a, b, c) on which p + (e, e^2, e^3) lies: the 3D orientation, or where
 *  p is on the plane the leading component of the normal (b - a) x (c - a), each an orientation of
 *  the triangle seen along an axis. `planSide` is the normal's z component's sign. */
int sideOfPlane(const Point3& a, const Point3& b, const Point3& c, const Point3& p, int planSide)
{
  const int side = static_cast<int>(CGAL::orientation(Kernel::Point_3(a.x, a.y, a.z), Kernel::Point_3(b.x, b.y, b.z),
                                                      Kernel::Point_3(c.x, c.y, c.z), Kernel::Point_3(p.x, p.y, p.z)));
  if (side != 0)
    return side;
  if (const int nx = orientation2(a.y, a.z, b.y, b.z, c.y, c.z); nx != 0)
    return nx;
  if (const int ny = orientation2(a.z, a.x, b.z, b.x, c.z, c.x); ny != 0)
    return ny;
  return planSide;
}

/** Whether the upward ray from the moved p crosses the triangle (a, b, c). */
bool rayCrosses(const Point3& a, const Point3& b, const Point3& c, const Point3& p)
{
  const int ab = sideOfEdge(a, b, p);
  if (ab == 0 || sideOfEdge(b, c, p) != ab || sideOfEdge(c, a, p) != ab)
    return false; // outside the triangle's plan, or the triangle is an edge in plan
  // ab is the sign of the normal's z: the plane is above p where p lies on its lower side.
  return sideOfPlane(a, b, c, p, ab) == -ab;
}

} // namespace

std::vector<char> pointsInside(const TriangleMesh& surface, const std::vector<Point3>& points, unsigned int threads)
{
  std::vector<char> inside(points.size(), 0);
  if (points.empty() || surface.triangles.empty())
    return inside;
  // The points filed in cells of the plane about one point a cell over their plan box (at most
  // 1024 a side); a triangle looks in the cells of its plan box within that box. A point with a
  // coordinate that is no number is filed nowhere: outside.
  const double infinity = std::numeric_limits<double>::infinity();
  Box2 plan{ infinity, infinity, -infinity, -infinity };
  for (const Point3& p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      plan = { std::min(plan.xmin, p.x), std::min(plan.ymin, p.y), std::max(plan.xmax, p.x), std::max(plan.ymax, p.y) };
  const double side = std::clamp(std::ceil(std::sqrt(static_cast<double>(points.size()))), 1.0, 1024.0);
  const double width = std::max(plan.xmax - plan.xmin, plan.ymax - plan.ymin);
  SpatialHash grid(width > 0.0 ? width / side : 1.0);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::isfinite(points[i].x) && std::isfinite(points[i].y))
      grid.insert(Point2{ points[i].x, points[i].y }, static_cast<int>(i));
  // Each range of triangles lists the points its triangles are above; the parity of a point's
  // listings does not depend on the order they are taken in.
  constexpr std::size_t rangeSize = 1 << 15;
  const auto crossed = fixedRangeResults<std::vector<std::uint32_t>>(
    surface.triangles.size(), rangeSize, threads,
    [&](std::vector<std::uint32_t>& hits, std::size_t first, std::size_t last)
    {
      for (std::size_t t = first; t < last; ++t)
      {
        const Triangle& tri = surface.triangles[t];
        const Point3& a = surface.points[static_cast<std::size_t>(tri[0])];
        const Point3& b = surface.points[static_cast<std::size_t>(tri[1])];
        const Point3& c = surface.points[static_cast<std::size_t>(tri[2])];
        const double lowX = std::min({ a.x, b.x, c.x }), highX = std::max({ a.x, b.x, c.x });
        const double lowY = std::min({ a.y, b.y, c.y }), highY = std::max({ a.y, b.y, c.y });
        const Box2 under{ std::max(lowX, plan.xmin), std::max(lowY, plan.ymin), std::min(highX, plan.xmax),
                          std::min(highY, plan.ymax) };
        if (under.xmin > under.xmax || under.ymin > under.ymax)
          continue;
        grid.forEachIn(grid.cellsOf(under),
                       [&](int i)
                       {
                         const Point3& p = points[static_cast<std::size_t>(i)];
                         // The moved point's plan lies in [low, high) on each axis at most.
                         if (p.x < lowX || p.x >= highX || p.y < lowY || p.y >= highY)
                           return;
                         if (rayCrosses(a, b, c, p))
                           hits.push_back(static_cast<std::uint32_t>(i));
                       });
      }
    });
  for (const std::vector<std::uint32_t>& hits : crossed)
    for (std::uint32_t i : hits)
      inside[i] ^= 1;
  return inside;
}

} // namespace slicemesh

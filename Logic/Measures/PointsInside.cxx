#include "Measures/PointsInside.h"

#include "Core/ParallelFor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

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

/** The points bucketed by a uniform grid over their plan box, about one point a cell. */
class PlanGrid
{
public:
  explicit PlanGrid(const std::vector<Point3>& points)
  {
    m_Low = { points.front().x, points.front().y };
    m_High = m_Low;
    for (const Point3& p : points)
    {
      m_Low = { std::min(m_Low[0], p.x), std::min(m_Low[1], p.y) };
      m_High = { std::max(m_High[0], p.x), std::max(m_High[1], p.y) };
    }
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(points.size()))));
    m_Cells = std::clamp<std::size_t>(side, 1, 1024);
    for (int axis = 0; axis < 2; ++axis)
      m_Size[axis] = std::max((m_High[axis] - m_Low[axis]) / static_cast<double>(m_Cells), 1e-300);
    m_Start.assign(m_Cells * m_Cells + 1, 0);
    std::vector<std::size_t> cellOf(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      cellOf[i] = cell(0, points[i].x) * m_Cells + cell(1, points[i].y);
      ++m_Start[cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < m_Cells * m_Cells; ++c)
      m_Start[c + 1] += m_Start[c];
    m_Points.resize(points.size());
    std::vector<std::uint32_t> next(m_Start.begin(), m_Start.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
      m_Points[next[cellOf[i]]++] = static_cast<std::uint32_t>(i);
  }

  /** Calls visit(i) for each point in the cells that the plan box [low, high] covers. */
  template <typename Visit>
  void forPointsUnder(double lowX, double lowY, double highX, double highY, Visit&& visit) const
  {
    if (highX < m_Low[0] || lowX > m_High[0] || highY < m_Low[1] || lowY > m_High[1])
      return;
    const std::size_t x0 = cell(0, lowX), x1 = cell(0, highX), y0 = cell(1, lowY), y1 = cell(1, highY);
    for (std::size_t x = x0; x <= x1; ++x)
      for (std::uint32_t k = m_Start[x * m_Cells + y0]; k < m_Start[x * m_Cells + y1 + 1]; ++k)
        visit(m_Points[k]);
  }

private:
  std::size_t cell(int axis, double value) const
  {
    const double c = std::floor((value - m_Low[axis]) / m_Size[axis]);
    return c > 0.0 ? static_cast<std::size_t>(std::min(c, static_cast<double>(m_Cells - 1))) : 0; // NaN: 0
  }

  std::array<double, 2> m_Low{}, m_High{}, m_Size{};
  std::size_t m_Cells = 1;
  std::vector<std::uint32_t> m_Start;  // per cell (x-major), its first entry in m_Points
  std::vector<std::uint32_t> m_Points; // point indices, cell by cell
};

} // namespace

std::vector<char> pointsInside(const TriangleMesh& surface, const std::vector<Point3>& points, unsigned int threads)
{
  std::vector<char> inside(points.size(), 0);
  if (points.empty() || surface.triangles.empty())
    return inside;
  const PlanGrid grid(points);
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
        grid.forPointsUnder(lowX, lowY, highX, highY,
                            [&](std::uint32_t i)
                            {
                              const Point3& p = points[i];
                              // The moved point's plan lies in [low, high) on each axis at most.
                              if (p.x < lowX || p.x >= highX || p.y < lowY || p.y >= highY)
                                return;
                              if (rayCrosses(a, b, c, p))
                                hits.push_back(i);
                            });
      }
    });
  for (const std::vector<std::uint32_t>& hits : crossed)
    for (std::uint32_t i : hits)
      inside[i] ^= 1;
  return inside;
}

} // namespace slicemesh

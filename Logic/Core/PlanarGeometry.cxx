#include "Core/PlanarGeometry.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

namespace slicemesh
{

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
Kernel::Point_2 toCgal(const Point2& p)
{
  return { p.x, p.y };
}
} // namespace

double twiceSignedArea(const Polygon2& polygon)
{
  double sum = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

double perimeter(const Polygon2& polygon)
{
  double length = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    length += distance(polygon[i], polygon[(i + 1) % polygon.size()]);
  return length;
}

int orientation(const Point2& a, const Point2& b, const Point2& c)
{
  switch (CGAL::orientation(toCgal(a), toCgal(b), toCgal(c)))
  {
    case CGAL::LEFT_TURN:
      return 1;
    case CGAL::RIGHT_TURN:
      return -1;
    default:
      return 0;
  }
}

bool isInside(const Polygon2& polygon, const Point2& p)
{
  // Winding test by upward/downward crossings of the horizontal ray to the right of p,
  // decided with exact orientation predicates.
  int winding = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    if (a.y <= p.y)
    {
      if (b.y > p.y)
      {
        const int o = orientation(a, b, p);
        if (o == 0)
          return false; // on the boundary
        if (o > 0)
          ++winding;
      }
      else if (b.y == p.y && a.y == p.y && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x))
        return false; // on a horizontal edge
    }
    else if (b.y <= p.y)
    {
      const int o = orientation(a, b, p);
      if (o == 0)
        return false;
      if (o < 0)
        --winding;
    }
  }
  return winding != 0;
}

Box2 boundingBox(const Polygon2& polygon)
{
  Box2 box;
  if (polygon.empty())
    return box;
  box.xmin = box.xmax = polygon[0].x;
  box.ymin = box.ymax = polygon[0].y;
  for (const Point2& p : polygon)
  {
    box.xmin = std::min(box.xmin, p.x);
    box.xmax = std::max(box.xmax, p.x);
    box.ymin = std::min(box.ymin, p.y);
    box.ymax = std::max(box.ymax, p.y);
  }
  return box;
}

void appendEdgeLengths(const std::vector<Polygon2>& contours, std::vector<double>& lengths)
{
  for (const Polygon2& polygon : contours)
    for (std::size_t i = 0; i < polygon.size(); ++i)
      lengths.push_back(distance(polygon[i], polygon[(i + 1) % polygon.size()]));
}

double median(std::vector<double> values, double fallback)
{
  if (values.empty())
    return fallback;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

} // namespace slicemesh

// Small exact-enough planar helpers shared by the Logic stages.
#ifndef PlanarGeometry_h
#define PlanarGeometry_h

#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

/** Twice the signed area of a closed polygon: positive when counter-clockwise. */
double twiceSignedArea(const Polygon2& polygon);

/** Length of a closed polygon's boundary, the closing edge included. */
double perimeter(const Polygon2& polygon);

/** Robust orientation of (a, b, c): +1 left turn, -1 right turn, 0 collinear (exact predicate). */
int orientation(const Point2& a, const Point2& b, const Point2& c);

/** Whether p is strictly inside the closed polygon (even-odd rule, exact predicates).
 *  Points on the boundary count as outside. */
bool isInside(const Polygon2& polygon, const Point2& p);

/** Squared distance from p to the segment ab, and the parameter t of the closest point. Inline: the
 *  nearest-segment searches call it in their inner loops. */
inline double squaredDistanceToSegment(const Point2& p, const Point2& a, const Point2& b, double* tOut = nullptr)
{
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = 0.0;
  if (len2 > 0.0)
    t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
  if (tOut)
    *tOut = t;
  const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
  return ex * ex + ey * ey;
}

/** Distance from p to the segment ab, and the parameter t of the closest point. */
inline double distanceToSegment(const Point2& p, const Point2& a, const Point2& b, double* t = nullptr)
{
  return std::sqrt(squaredDistanceToSegment(p, a, b, t));
}

/** Distances here take the square root of the sum of squares, not std::hypot: coordinates are
 *  millimetres, far from where squaring overflows, and hypot's guarding took 3-4% of a run. */
inline double distance(const Point2& a, const Point2& b)
{
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

struct Box2
{
  double xmin = 0.0, ymin = 0.0, xmax = -1.0, ymax = -1.0;
  bool overlaps(const Box2& o, double margin = 0.0) const
  {
    return xmin <= o.xmax + margin && o.xmin <= xmax + margin && ymin <= o.ymax + margin && o.ymin <= ymax + margin;
  }
};

Box2 boundingBox(const Polygon2& polygon);

/** Appends the length of every edge of the closed contours to lengths. */
void appendEdgeLengths(const std::vector<Polygon2>& contours, std::vector<double>& lengths);

/** The median of the values (the upper one for an even count), or fallback when there are none. */
double median(std::vector<double> values, double fallback);

} // namespace slicemesh

#endif

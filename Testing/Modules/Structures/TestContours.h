// Contours with known areas for the structure-set tests: circles, annuli, keyholes, in LPS mm.
#ifndef TestContours_h
#define TestContours_h

#include "Contours/ContourStacking.h"

#include <cmath>

namespace slicemesh::testing
{

constexpr double Pi = 3.14159265358979323846;

/** n points on a circle of radius r about (cx, cy) in the plane z (LPS mm), counter-clockwise seen
 *  from +z unless `clockwise`. */
inline Polygon3 circle(double cx, double cy, double z, double r, int n = 96, bool clockwise = false)
{
  Polygon3 points;
  for (int k = 0; k < n; ++k)
  {
    const double angle = (clockwise ? -2.0 : 2.0) * Pi * k / n;
    points.push_back({ cx + r * std::cos(angle), cy + r * std::sin(angle), z });
  }
  return points;
}

/** Area of the regular n-gon inscribed in a circle of radius r: what circle() encloses. */
inline double polygonArea(double r, int n = 96)
{
  return 0.5 * n * r * r * std::sin(2.0 * Pi / n);
}

/** An annulus about (cx, cy) as one keyhole contour: the outer circle counter-clockwise, in along
 *  a channel of `width` mm at angle 0, the hole clockwise, and back out. width 0: the channel's two
 *  sides lie on each other. */
inline Polygon3 keyholeAnnulus(double cx, double cy, double z, double outer, double inner, double width, int n = 96)
{
  const double alphaOuter = std::asin(0.5 * width / outer), alphaInner = std::asin(0.5 * width / inner);
  Polygon3 points;
  // The channel's ends exactly, so that a zero-width channel's sides lie exactly on each other.
  auto add = [&](double radius, double angle, bool end)
  {
    if (end && width == 0.0)
      points.push_back({ cx + radius, cy, z });
    else
      points.push_back({ cx + radius * std::cos(angle), cy + radius * std::sin(angle), z });
  };
  for (int k = 0; k <= n; ++k)
    add(outer, alphaOuter + (2.0 * Pi - 2.0 * alphaOuter) * k / n, k == 0 || k == n);
  for (int k = 0; k <= n; ++k)
    add(inner, -alphaInner - (2.0 * Pi - 2.0 * alphaInner) * k / n, k == 0 || k == n);
  return points;
}

/** The contour moved by (dx, dy, dz). */
inline Polygon3 moved(Polygon3 contour, double dx, double dy, double dz)
{
  for (Point3& p : contour)
    p = { p.x + dx, p.y + dy, p.z + dz };
  return contour;
}

} // namespace slicemesh::testing

#endif

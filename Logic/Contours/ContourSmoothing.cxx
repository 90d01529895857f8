// Taubin's lambda/mu smoothing on closed polygons: G. Taubin, "A signal processing approach to fair
// surface design", SIGGRAPH 1995 (the umbrella operator on a closed curve, alternating a shrinking
// step lambda > 0 and an inflating step mu < -lambda).
#include "Contours/ContourSmoothing.h"

#include "Contours/ContourCrossings.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace slicemesh
{
namespace
{

/** One umbrella step on the closed polygon: p_i += factor * (mean of neighbours - p_i). */
void umbrellaStep(Polygon2& points, double factor, Polygon2& scratch)
{
  const std::size_t n = points.size();
  scratch.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& previous = points[(i + n - 1) % n];
    const Point2& next = points[(i + 1) % n];
    scratch[i] = { points[i].x + factor * (0.5 * (previous.x + next.x) - points[i].x),
                   points[i].y + factor * (0.5 * (previous.y + next.y) - points[i].y) };
  }
  points.swap(scratch);
}

/** Pulls every point back to within `radius` of its original position. */
void clampTo(Polygon2& points, const Polygon2& original, double radius)
{
  if (!(radius > 0.0))
    return;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double dx = points[i].x - original[i].x, dy = points[i].y - original[i].y;
    const double length = std::hypot(dx, dy);
    if (length > radius)
      points[i] = { original[i].x + dx * radius / length, original[i].y + dy * radius / length };
  }
}

/** Moves every point by `offset` along its normal, the normal to the right of the direction of
 *  travel: outwards on a counter-clockwise contour, inwards on a clockwise one, so the signed area
 *  grows by about offset times the perimeter either way. */
void offsetAlongNormals(Polygon2& points, double offset)
{
  const std::size_t n = points.size();
  Polygon2 moved(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& previous = points[(i + n - 1) % n];
    const Point2& next = points[(i + 1) % n];
    // The normal of the chord previous -> next: the average direction of the two edges at i.
    const double dx = next.x - previous.x, dy = next.y - previous.y;
    const double length = std::hypot(dx, dy);
    moved[i] = length > 0.0 ? Point2{ points[i].x + offset * dy / length, points[i].y - offset * dx / length } : points[i];
  }
  points.swap(moved);
}

} // namespace

void offsetToArea(Polygon2& contour, double area, const Polygon2* anchor, double maxDisplacement)
{
  if (contour.size() < 3)
    return;
  // Newton steps on the common offset: the first-order estimate offset = dA / perimeter is off by
  // the curvature term on small contours, and the clamp may cut it.
  for (int step = 0; step < 6; ++step)
  {
    const double deficit = area - 0.5 * twiceSignedArea(contour);
    const double length = perimeter(contour);
    if (!(length > 0.0) || std::abs(deficit) <= 1e-9 * std::abs(area))
      break;
    offsetAlongNormals(contour, deficit / length);
    if (anchor)
      clampTo(contour, *anchor, maxDisplacement);
  }
}

Polygon2 smoothContour(const Polygon2& contour, const ContourSmoothingOptions& options)
{
  if (options.iterations <= 0 || contour.size() < 4)
    return contour;
  Polygon2 points = contour, scratch;
  for (int iteration = 0; iteration < options.iterations; ++iteration)
  {
    umbrellaStep(points, options.lambda, scratch);
    umbrellaStep(points, options.mu, scratch);
    clampTo(points, contour, options.maxDisplacement);
  }

  offsetToArea(points, 0.5 * twiceSignedArea(contour), &contour, options.maxDisplacement);
  return points;
}

std::vector<Polygon2> smoothContours(const std::vector<Polygon2>& contours, const ContourSmoothingOptions& options)
{
  if (options.iterations <= 0)
    return contours;
  std::vector<Polygon2> result(contours.size());
  for (std::size_t c = 0; c < contours.size(); ++c)
    result[c] = smoothContour(contours[c], options);

  // Safety net: put offending contours back as traced until nothing crosses. Ends: every round
  // restores at least one smoothed contour, and the traced contours do not cross (or, when they
  // do, those pairs are all restored and stay so).
  std::vector<char> restored(contours.size(), 0);
  for (;;)
  {
    std::set<std::size_t> offending;
    for (const auto& [e, f] : contourCrossings(result))
    {
      if (!restored[e.contour])
        offending.insert(e.contour);
      if (!restored[f.contour])
        offending.insert(f.contour);
    }
    if (offending.empty())
      break;
    for (std::size_t c : offending)
    {
      result[c] = contours[c];
      restored[c] = 1;
    }
  }
  return result;
}

ContourStack smoothContours(const ContourStack& stack, const ContourSmoothingOptions& options)
{
  ContourStack result = stack;
  for (Slice& slice : result.slices)
    slice.contours = smoothContours(slice.contours, options);
  return result;
}

} // namespace slicemesh

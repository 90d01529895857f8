#include "Contours/ContourResampling.h"

#include "Contours/ContourCrossings.h"
#include "Contours/ContourSmoothing.h"
#include "Core/ArcLengthWalk.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace slicemesh
{

namespace
{

/** Appends to `out` the points at arc lengths step, 2 step, ... (count - 1) step along the `edges`
 *  edges of the closed contour that follow its point `from` (round past its last point). */
void appendEvenSteps(const Polygon2& contour, std::size_t from, std::size_t edges, double step, std::size_t count,
                     Polygon2& out)
{
  ArcLengthWalk walk(contour, from, edges);
  for (std::size_t k = 1; k < count; ++k)
  {
    const double s = static_cast<double>(k) * step;
    walk.reach(s); // s past the stretch's end (by rounding) gives its end
    out.push_back(walk.onEdgeAt(s));
  }
}

} // namespace

Polygon2 resampleContour(const Polygon2& contour, double spacing)
{
  const double length = perimeter(contour);
  if (!(spacing > 0.0) || contour.size() < 2 || !(length > 0.0))
    return contour;
  // A small contour (a speck, a vessel a few pixels across) keeps enough points for its shape: a
  // circle of three points is a triangle, and the tiling of such contours between slices folds.
  const std::size_t fewest = std::max<std::size_t>(3, std::min(contour.size(), fewestResampledPoints));
  const std::size_t count = std::max(fewest, static_cast<std::size_t>(std::llround(length / spacing)));
  const double step = length / static_cast<double>(count);

  Polygon2 resampled;
  resampled.reserve(count);
  resampled.push_back(contour.front());
  appendEvenSteps(contour, 0, contour.size(), step, count, resampled);
  return resampled;
}

std::vector<std::size_t> contourCorners(const Polygon2& contour, double spacing, double turnDegrees)
{
  const std::size_t n = contour.size();
  if (n < 3)
    return {};
  const double cosine = std::cos(turnDegrees * M_PI / 180.0);
  // Each point's turn (the cosine between its incoming and outgoing edges) and arc length.
  std::vector<double> turn(n, 1.0), arc(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& previous = contour[(i + n - 1) % n];
    const Point2& p = contour[i];
    const Point2& next = contour[(i + 1) % n];
    const double ax = p.x - previous.x, ay = p.y - previous.y, bx = next.x - p.x, by = next.y - p.y;
    const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
    turn[i] = la > 0.0 && lb > 0.0 ? (ax * bx + ay * by) / (la * lb) : 1.0;
    arc[i + 1] = arc[i] + lb;
  }
  const double length = arc[n];
  std::vector<std::size_t> sharp;
  for (std::size_t i = 0; i < n; ++i)
    if (turn[i] < cosine)
      sharp.push_back(i);
  // Sharpest first; a corner within half a spacing of a sharper one (along the contour, either way
  // round) is not kept.
  std::stable_sort(sharp.begin(), sharp.end(), [&](std::size_t a, std::size_t b) { return turn[a] < turn[b]; });
  std::vector<std::size_t> corners;
  for (std::size_t i : sharp)
  {
    const bool crowded = std::any_of(corners.begin(), corners.end(),
                                     [&](std::size_t c)
                                     {
                                       const double along = std::abs(arc[i] - arc[c]);
                                       return std::min(along, length - along) < 0.5 * spacing;
                                     });
    if (!crowded)
      corners.push_back(i);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

Polygon2 resampleContourKeepingCorners(const Polygon2& contour, double spacing)
{
  if (!(spacing > 0.0) || contour.size() < 3 || !(perimeter(contour) > 0.0))
    return contour;
  // A small drawn contour keeps more of its points than a traced one: its shape is the anatomy.
  spacing = std::min(spacing, perimeter(contour) / static_cast<double>(std::min(contour.size(), fewestDrawnPoints)));
  const std::vector<std::size_t> corners = contourCorners(contour, spacing);
  if (corners.empty())
    return resampleContour(contour, spacing);
  const std::size_t n = contour.size();
  Polygon2 resampled;
  for (std::size_t k = 0; k < corners.size(); ++k)
  {
    // The stretch from this corner to the next (round to the first), as an open polyline.
    const std::size_t from = corners[k], to = corners[(k + 1) % corners.size()];
    const std::size_t points = (to + n - from) % n == 0 ? n : (to + n - from) % n;
    const double length = arcLength(contour, from, points);
    const std::size_t steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(length / spacing)));
    const double step = length / static_cast<double>(steps);
    resampled.push_back(contour[from]);
    appendEvenSteps(contour, from, points, step, steps, resampled);
  }
  // A small contour keeps enough points for its shape, as resampleContour leaves it.
  const std::size_t fewest = std::max<std::size_t>(3, std::min(contour.size(), fewestResampledPoints));
  if (resampled.size() < fewest)
    return resampled.size() * 2 >= fewest ? resampleContourKeepingCorners(contour, 0.5 * spacing) : contour;
  return resampled;
}

Polygon2 resampleContourKeepingArea(const Polygon2& contour, double spacing)
{
  Polygon2 resampled = resampleContour(contour, spacing);
  offsetToArea(resampled, 0.5 * twiceSignedArea(contour));
  return resampled;
}

std::vector<Polygon2> resampleContours(const std::vector<Polygon2>& contours, double spacing, ResampledShape shape)
{
  auto resample = [shape](const Polygon2& contour, double step) {
    switch (shape)
    {
      case ResampledShape::KeepingArea: return resampleContourKeepingArea(contour, step);
      case ResampledShape::KeepingCorners: return resampleContourKeepingCorners(contour, step);
      case ResampledShape::Chords: break;
    }
    return resampleContour(contour, step);
  };
  if (!(spacing > 0.0))
    return contours;
  std::vector<Polygon2> result(contours.size());
  std::vector<double> spacings(contours.size(), spacing);
  std::vector<char> original(contours.size(), 0);
  for (std::size_t c = 0; c < contours.size(); ++c)
    result[c] = resample(contours[c], spacing);

  constexpr int attempts = 4;
  for (int attempt = 0; attempt <= attempts; ++attempt)
  {
    std::set<std::size_t> offending;
    for (const auto& [e, f] : contourCrossings(result))
    {
      offending.insert(e.contour);
      offending.insert(f.contour);
    }
    bool changed = false;
    for (std::size_t c : offending)
    {
      if (original[c])
        continue;
      changed = true;
      spacings[c] *= 0.5;
      if (attempt == attempts)
      {
        result[c] = contours[c];
        original[c] = 1;
      }
      else
        result[c] = resample(contours[c], spacings[c]);
    }
    if (!changed)
      break;
  }
  return result;
}

ContourStack resampleContours(const ContourStack& stack, double spacing, ResampledShape shape)
{
  ContourStack result = stack;
  for (Slice& slice : result.slices)
    slice.contours = resampleContours(slice.contours, spacing, shape);
  return result;
}

double meanPointSpacing(const ContourStack& stack)
{
  double length = 0.0;
  std::size_t edges = 0;
  for (const Slice& slice : stack.slices)
    for (const Polygon2& contour : slice.contours)
      if (contour.size() >= 2)
      {
        length += perimeter(contour);
        edges += contour.size();
      }
  return edges ? length / static_cast<double>(edges) : 0.0;
}

} // namespace slicemesh

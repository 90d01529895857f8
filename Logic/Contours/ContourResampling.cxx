#include "Contours/ContourResampling.h"

#include "Contours/ContourCrossings.h"
#include "Contours/ContourSmoothing.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace slicemesh
{

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
  std::size_t edge = 0;          // current edge: contour[edge] -> contour[edge + 1]
  double edgeStart = 0.0;        // arc length at contour[edge]
  double edgeLength = distance(contour[0], contour[1 % contour.size()]);
  for (std::size_t k = 1; k < count; ++k)
  {
    const double s = k * step;
    while (edgeStart + edgeLength < s && edge + 1 < contour.size())
    {
      edgeStart += edgeLength;
      ++edge;
      edgeLength = distance(contour[edge], contour[(edge + 1) % contour.size()]);
    }
    const Point2& a = contour[edge];
    const Point2& b = contour[(edge + 1) % contour.size()];
    const double t = edgeLength > 0.0 ? std::clamp((s - edgeStart) / edgeLength, 0.0, 1.0) : 0.0;
    resampled.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) });
  }
  return resampled;
}

Polygon2 resampleContourKeepingArea(const Polygon2& contour, double spacing)
{
  Polygon2 resampled = resampleContour(contour, spacing);
  offsetToArea(resampled, 0.5 * twiceSignedArea(contour));
  return resampled;
}

std::vector<Polygon2> resampleContours(const std::vector<Polygon2>& contours, double spacing, bool keepArea)
{
  auto resample = [keepArea](const Polygon2& contour, double step) {
    return keepArea ? resampleContourKeepingArea(contour, step) : resampleContour(contour, step);
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

ContourStack resampleContours(const ContourStack& stack, double spacing, bool keepArea)
{
  ContourStack result = stack;
  for (Slice& slice : result.slices)
    slice.contours = resampleContours(slice.contours, spacing, keepArea);
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

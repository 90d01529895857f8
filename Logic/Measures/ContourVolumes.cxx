#include "Measures/ContourVolumes.h"

#include "Contours/ContourNesting.h"
#include "Core/PlanarGeometry.h"
#include "Measures/StackVolume.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{
namespace
{

/** How many points (i * pixel[0], j * pixel[1]) lie inside the polygon, row by row: each edge
 *  counts on a row it crosses by the half-open rule (one end below or on the row, the other above),
 *  so a corner on a row is counted once. A traced contour passes half a pixel from the centres. */
double pixelCentresInside(const Polygon2& polygon, const std::array<double, 2>& pixel)
{
  double ymin = polygon.front().y, ymax = ymin;
  for (const Point2& p : polygon)
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  double count = 0.0;
  std::vector<double> crossings;
  for (long long j = static_cast<long long>(std::ceil(ymin / pixel[1])); j * pixel[1] <= ymax; ++j)
  {
    const double y = static_cast<double>(j) * pixel[1];
    crossings.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % polygon.size()];
      if ((a.y <= y) != (b.y <= y))
        crossings.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t c = 0; c + 1 < crossings.size(); c += 2)
    {
      // The centres strictly between the two crossings.
      const double first = std::floor(crossings[c] / pixel[0]) + 1.0;
      const double last = std::ceil(crossings[c + 1] / pixel[0]) - 1.0;
      count += std::max(0.0, last - first + 1.0);
    }
  }
  return count;
}

} // namespace

std::vector<ContourVolume> contourVolumes(const ContourStack& stack, const std::array<double, 2>& pixel)
{
  const bool onPixels = pixel[0] > 0.0 && pixel[1] > 0.0;
  std::vector<ContourVolume> shares;
  for (std::size_t k = 0; k < stack.slices.size(); ++k)
  {
    const Slice& slice = stack.slices[k];
    const double thickness = onPixels && stack.sliceSpacing > 0.0 ? stack.sliceSpacing : sliceThickness(stack, k);
    std::vector<Polygon2> contours = slice.contours;
    const ContourNesting nesting = orientAndNest(contours);
    for (std::size_t c = 0; c < contours.size(); ++c)
    {
      if (contours[c].empty())
        continue;
      const double area = onPixels ? pixelCentresInside(contours[c], pixel) * pixel[0] * pixel[1]
                                   : 0.5 * std::abs(twiceSignedArea(contours[c]));
      const Point2& at = slice.contours[c].front();
      shares.push_back({ { at.x, at.y, slice.z }, (nesting.isHole(c) ? -area : area) * thickness });
    }
  }
  return shares;
}

} // namespace slicemesh

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
 *  so a corner on a row is counted once. A traced contour passes half a pixel from the centres.
 *  The crossings are found edge by edge (an edge of a traced contour crosses a row or two), not row
 *  by row over every edge, which grew with the rows times the points: quadratic in the resolution. */
double pixelCentresInside(const Polygon2& polygon, const std::array<double, 2>& pixel)
{
  struct Crossing
  {
    long long row;
    double x;
  };
  std::vector<Crossing> crossings;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
    // One row either side of the edge's span, each tested by the rule itself: the rows' heights are
    // products j * pixel, whose rounding the division need not match.
    for (long long j = static_cast<long long>(std::floor(low / pixel[1])) - 1;
         static_cast<double>(j - 1) * pixel[1] <= high; ++j)
    {
      const double y = static_cast<double>(j) * pixel[1];
      if ((a.y <= y) != (b.y <= y))
        crossings.push_back({ j, a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x) });
    }
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& p, const Crossing& q) { return p.row != q.row ? p.row < q.row : p.x < q.x; });
  double count = 0.0;
  for (std::size_t c = 0; c + 1 < crossings.size(); c += 2)
  {
    // The centres strictly between the two crossings of a row (a closed polygon crosses each row an
    // even number of times, so pairs never straddle two rows).
    const double first = std::floor(crossings[c].x / pixel[0]) + 1.0;
    const double last = std::ceil(crossings[c + 1].x / pixel[0]) - 1.0;
    count += std::max(0.0, last - first + 1.0);
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

// Douglas-Peucker with Saalfeld's repair: D. Douglas, T. Peucker, "Algorithms for the reduction of
// the number of points required to represent a digitized line", Cartographica 10(2), 1973;
// A. Saalfeld, "Topologically consistent line simplification with the Douglas-Peucker algorithm",
// Cartography and GIS 26(1), 1999 (put back the farthest dropped point of an offending edge).
#include "Contours/ContourSimplification.h"

#include "Contours/ContourCrossings.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{
namespace
{

/** The index, among the points strictly between first and last (cyclic), farthest from the chord;
 *  n (none) when there is no point between them. */
std::size_t farthestBetween(const Polygon2& polygon, std::size_t first, std::size_t last, double* farthest)
{
  const std::size_t n = polygon.size();
  std::size_t best = n;
  double bestDistance = -1.0;
  for (std::size_t i = (first + 1) % n; i != last; i = (i + 1) % n)
  {
    const double d = distanceToSegment(polygon[i], polygon[first], polygon[last]);
    if (d > bestDistance)
    {
      bestDistance = d;
      best = i;
    }
  }
  if (farthest)
    *farthest = bestDistance;
  return best;
}

/** The point half way between first and last (cyclic) by count; n when there is none between. */
std::size_t middleBetween(const Polygon2& polygon, std::size_t first, std::size_t last)
{
  const std::size_t n = polygon.size();
  const std::size_t between = (last + n - first) % n;
  return between < 2 ? n : (first + between / 2) % n;
}

void douglasPeucker(const Polygon2& polygon, std::size_t first, std::size_t last, double tolerance,
                    double maxEdgeLength, std::vector<char>& kept)
{
  // An explicit stack: contours of many thousand points must not recurse that deep.
  std::vector<std::pair<std::size_t, std::size_t>> spans{ { first, last } };
  while (!spans.empty())
  {
    const auto [a, b] = spans.back();
    spans.pop_back();
    double d = 0.0;
    std::size_t split = farthestBetween(polygon, a, b, &d);
    if (split != polygon.size() && d <= tolerance)
      split = maxEdgeLength > 0.0 && distance(polygon[a], polygon[b]) > maxEdgeLength ? middleBetween(polygon, a, b)
                                                                                      : polygon.size();
    if (split == polygon.size())
      continue;
    kept[split] = 1;
    spans.push_back({ a, split });
    spans.push_back({ split, b });
  }
}

std::vector<std::size_t> keptIndices(const std::vector<char>& kept)
{
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (kept[i])
      indices.push_back(i);
  return indices;
}

/** The contour still a proper polygon: at least 3 points, and at least half the area it had as
 *  traced. A contour thinner than the tolerance (a bar one voxel thick) otherwise falls to a
 *  triangle or a sliver of almost no area, which no surface can be tiled from; half is where the
 *  simplified outline stops standing for the traced one. */
bool isProperPolygon(const Polygon2& polygon, const std::vector<char>& kept)
{
  Polygon2 simplified;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (kept[i])
      simplified.push_back(polygon[i]);
  return simplified.size() >= std::min<std::size_t>(3, polygon.size()) &&
         std::abs(twiceSignedArea(simplified)) >= 0.5 * std::abs(twiceSignedArea(polygon));
}

/** Puts back the dropped point farthest from the kept edge that replaced it; false when none is
 *  left (every point kept). */
bool putBackFarthestDropped(const Polygon2& polygon, std::vector<char>& kept)
{
  const std::vector<std::size_t> k = keptIndices(kept);
  std::size_t best = polygon.size();
  double bestDistance = -1.0;
  for (std::size_t e = 0; e < k.size(); ++e)
  {
    double d = 0.0;
    const std::size_t split = farthestBetween(polygon, k[e], k[(e + 1) % k.size()], &d);
    if (split != polygon.size() && d > bestDistance)
    {
      bestDistance = d;
      best = split;
    }
  }
  if (best == polygon.size())
    return false;
  kept[best] = 1;
  return true;
}

} // namespace

std::vector<Polygon2> simplifyContours(const std::vector<Polygon2>& contours, double tolerance, double maxEdgeLength)
{
  if (!(tolerance > 0.0))
    return contours;

  std::vector<std::vector<char>> kept(contours.size());
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    const Polygon2& polygon = contours[c];
    const std::size_t n = polygon.size();
    kept[c].assign(n, n <= 3 ? 1 : 0);
    if (n <= 3)
      continue;
    // Anchors: the first point and the point farthest from it.
    std::size_t far = 0;
    double farDistance = -1.0;
    for (std::size_t i = 1; i < n; ++i)
      if (const double d = distance(polygon[i], polygon[0]); d > farDistance)
      {
        farDistance = d;
        far = i;
      }
    kept[c][0] = kept[c][far] = 1;
    douglasPeucker(polygon, 0, far, tolerance, maxEdgeLength, kept[c]);
    douglasPeucker(polygon, far, 0, tolerance, maxEdgeLength, kept[c]);
    while (!isProperPolygon(polygon, kept[c]) && putBackFarthestDropped(polygon, kept[c]))
    {
    }
  }

  // Saalfeld's repair: put back points until no two kept edges meet. Each round adds at least one
  // point or stops; an edge of the input itself cannot be split further.
  for (;;)
  {
    std::vector<std::vector<std::size_t>> indices(contours.size());
    std::vector<Polygon2> simplified(contours.size());
    for (std::size_t c = 0; c < contours.size(); ++c)
    {
      indices[c] = keptIndices(kept[c]);
      for (std::size_t i : indices[c])
        simplified[c].push_back(contours[c][i]);
    }
    bool added = false;
    auto splitEdge = [&](const ContourEdge& e)
    {
      const std::vector<std::size_t>& k = indices[e.contour];
      const std::size_t a = k[e.edge], b = k[(e.edge + 1) % k.size()];
      const std::size_t split = farthestBetween(contours[e.contour], a, b, nullptr);
      if (split != contours[e.contour].size() && !kept[e.contour][split])
      {
        kept[e.contour][split] = 1;
        added = true;
      }
    };
    for (const auto& [e, f] : contourCrossings(simplified))
    {
      splitEdge(e);
      splitEdge(f);
    }
    if (!added)
      return simplified;
  }
}

ContourStack simplifyContours(const ContourStack& stack, double tolerance, double maxEdgeLength)
{
  ContourStack result = stack;
  for (Slice& slice : result.slices)
    slice.contours = simplifyContours(slice.contours, tolerance, maxEdgeLength);
  return result;
}

} // namespace slicemesh

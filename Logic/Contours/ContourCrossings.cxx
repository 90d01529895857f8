#include "Contours/ContourCrossings.h"

#include "Core/PlanarGeometry.h"

#include <algorithm>

namespace slicemesh
{
namespace
{

bool onSegment(const Point2& a, const Point2& b, const Point2& p)
{
  // p is collinear with ab (checked by the caller): inside ab's box.
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/** Closed segments ab and cd share a point. */
bool segmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0)
    return true;
  if (o1 == 0 && onSegment(a, b, c))
    return true;
  if (o2 == 0 && onSegment(a, b, d))
    return true;
  if (o3 == 0 && onSegment(c, d, a))
    return true;
  if (o4 == 0 && onSegment(c, d, b))
    return true;
  return false;
}

/** Consecutive edges ab, bc fold back onto each other (collinear, c back towards a). */
bool foldsBack(const Point2& a, const Point2& b, const Point2& c)
{
  return orientation(a, b, c) == 0 && (a.x - b.x) * (c.x - b.x) + (a.y - b.y) * (c.y - b.y) > 0.0;
}

/** Closed segments ab and cd come within `gap` of each other (share a point when gap is 0). */
bool segmentsWithin(const Point2& a, const Point2& b, const Point2& c, const Point2& d, double gap)
{
  if (segmentsMeet(a, b, c, d))
    return true;
  // Apart, their closest points include an end of one of them.
  return gap > 0.0 && std::min({ distanceToSegment(a, c, d), distanceToSegment(b, c, d), distanceToSegment(c, a, b),
                                 distanceToSegment(d, a, b) }) <= gap;
}

/** The pairs of edges within `gap` of each other, apart from consecutive edges of one contour (which
 *  meet at their vertex) unless they fold back onto each other: a sweep over x of the edges' boxes
 *  grown by gap. */
std::vector<std::pair<ContourEdge, ContourEdge>> edgesWithin(const std::vector<Polygon2>& contours, double gap)
{
  struct Item
  {
    double xmin, xmax, ymin, ymax;
    ContourEdge edge;
  };
  std::vector<Item> items;
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    const Polygon2& polygon = contours[c];
    const std::size_t n = polygon.size();
    if (n < 2)
      continue;
    for (std::size_t e = 0; e < n; ++e)
    {
      const Point2& a = polygon[e];
      const Point2& b = polygon[(e + 1) % n];
      items.push_back({ std::min(a.x, b.x) - gap, std::max(a.x, b.x) + gap, std::min(a.y, b.y) - gap,
                        std::max(a.y, b.y) + gap, { c, e } });
    }
  }
  std::sort(items.begin(), items.end(),
            [](const Item& l, const Item& r)
            { return l.xmin < r.xmin || (l.xmin == r.xmin && (l.edge.contour < r.edge.contour ||
                                                              (l.edge.contour == r.edge.contour && l.edge.edge < r.edge.edge))); });

  auto point = [&](const ContourEdge& e, std::size_t k)
  {
    const Polygon2& polygon = contours[e.contour];
    return polygon[(e.edge + k) % polygon.size()];
  };

  std::vector<std::pair<ContourEdge, ContourEdge>> crossings;
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    const Item& current = items[i];
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t j) { return items[j].xmax < current.xmin; }),
                 active.end());
    for (std::size_t j : active)
    {
      const Item& other = items[j];
      if (other.ymax < current.ymin || current.ymax < other.ymin)
        continue;
      const ContourEdge& e = current.edge;
      const ContourEdge& f = other.edge;
      const Point2 a = point(e, 0), b = point(e, 1), c = point(f, 0), d = point(f, 1);
      if (e.contour == f.contour)
      {
        const std::size_t n = contours[e.contour].size();
        if (n == 2)
          continue; // a two-point "contour": its two edges are the same segment
        const bool fThenE = (f.edge + 1) % n == e.edge;
        const bool eThenF = (e.edge + 1) % n == f.edge;
        if (fThenE || eThenF)
        {
          // Consecutive: they share a vertex by construction; they meet elsewhere only by folding back.
          const bool fold = fThenE ? foldsBack(c, d, b) : foldsBack(a, b, d);
          if (fold)
            crossings.push_back({ f, e });
          continue;
        }
      }
      if (segmentsWithin(a, b, c, d, gap))
        crossings.push_back({ f, e });
    }
    active.push_back(i);
  }
  return crossings;
}

} // namespace

std::vector<std::pair<ContourEdge, ContourEdge>> contourCrossings(const std::vector<Polygon2>& contours)
{
  return edgesWithin(contours, 0.0);
}

std::vector<std::pair<ContourEdge, ContourEdge>> contourEdgesWithin(const std::vector<Polygon2>& contours, double gap)
{
  return edgesWithin(contours, std::max(0.0, gap));
}

} // namespace slicemesh

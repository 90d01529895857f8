#include "Correspondence/MutualIntersections.h"

#include "Core/PlanarGeometry.h"
#include "Core/SpatialHash.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace slicemesh
{

namespace
{

struct EdgeRef
{
  int contour;
  int edge;
};

struct Insertion
{
  int contour;
  int edge;
  double t;
  Point2 point;
};

/** The edges of a slice's contours in a spatial hash of their boxes grown by a margin, to find the
 *  candidate pairs of edges in near-linear time. */
class EdgeGrid
{
public:
  /** `cellSize` as asked, doubled while the edges' boxes would cover more than eight cells each on
   *  average (boundedCellSize). */
  EdgeGrid(const std::vector<Polygon2>& contours, double cellSize, double margin)
    : m_Cells(boundedCellSize(contours, cellSize, margin))
    , m_Margin(margin)
  {
    for (int c = 0; c < static_cast<int>(contours.size()); ++c)
    {
      const Polygon2& polygon = contours[c];
      for (int e = 0; e < static_cast<int>(polygon.size()); ++e)
      {
        m_Cells.insert(cellsOf(polygon[e], polygon[(e + 1) % polygon.size()]), static_cast<int>(m_Edges.size()));
        m_Edges.push_back({ c, e });
      }
    }
  }

  /** Calls visit(edge) for the edges that share a cell with segment ab (an edge may come more than once). */
  template <typename Visit>
  void forEachNear(const Point2& a, const Point2& b, Visit visit) const
  {
    m_Cells.forEachIn(cellsOf(a, b), [&](int index) { visit(m_Edges[index]); });
  }

private:
  static Box2 grownBox(const Point2& a, const Point2& b, double margin)
  {
    return { std::min(a.x, b.x) - margin, std::min(a.y, b.y) - margin, std::max(a.x, b.x) + margin,
             std::max(a.y, b.y) + margin };
  }

  /** The cell size is chosen from a typical edge (the caller's median), and a slice whose edges are
   *  mostly tiny (contours drawn over each other on adjacent tilted planes, their rounding crossed
   *  at every few micrometres) gave a size at which each ordinary edge covered millions of cells:
   *  the grid then took all the machine's memory. The candidates found do not depend on the size. */
  static double boundedCellSize(const std::vector<Polygon2>& contours, double cellSize, double margin)
  {
    std::size_t edges = 0;
    for (const Polygon2& polygon : contours)
      edges += polygon.size();
    for (;; cellSize *= 2.0)
    {
      const SpatialHash grid(cellSize);
      double covered = 0.0;
      for (const Polygon2& polygon : contours)
        for (std::size_t e = 0; e < polygon.size(); ++e)
        {
          const SpatialHash::CellRange r = grid.cellsOf(grownBox(polygon[e], polygon[(e + 1) % polygon.size()], margin));
          covered += static_cast<double>(r.x1 - r.x0 + 1) * static_cast<double>(r.y1 - r.y0 + 1);
        }
      if (covered <= 8.0 * static_cast<double>(edges))
        return cellSize;
    }
  }

  SpatialHash::CellRange cellsOf(const Point2& a, const Point2& b) const
  {
    return m_Cells.cellsOf(grownBox(a, b, m_Margin));
  }

  SpatialHash m_Cells;
  double m_Margin;
  std::vector<EdgeRef> m_Edges;
};

double medianEdgeLength(const std::vector<Polygon2>& a, const std::vector<Polygon2>& b)
{
  std::vector<double> lengths;
  appendEdgeLengths(a, lengths);
  appendEdgeLengths(b, lengths);
  return std::max(median(std::move(lengths), 1.0), 1e-9);
}

/** Rebuilds each contour with its insertions placed along their edges. */
void applyInsertions(std::vector<Polygon2>& contours, std::vector<Insertion>& insertions, double tolerance)
{
  if (insertions.empty())
    return;
  std::sort(insertions.begin(), insertions.end(), [](const Insertion& x, const Insertion& y) {
    return std::tie(x.contour, x.edge, x.t) < std::tie(y.contour, y.edge, y.t);
  });
  std::size_t next = 0;
  for (int c = 0; c < static_cast<int>(contours.size()); ++c)
  {
    if (next >= insertions.size() || insertions[next].contour != c)
      continue;
    const Polygon2& old = contours[c];
    Polygon2 rebuilt;
    rebuilt.reserve(old.size() + 8);
    for (int e = 0; e < static_cast<int>(old.size()); ++e)
    {
      rebuilt.push_back(old[e]);
      const Point2& end = old[(e + 1) % old.size()];
      for (; next < insertions.size() && insertions[next].contour == c && insertions[next].edge == e; ++next)
      {
        const Point2& p = insertions[next].point;
        if (distance(p, rebuilt.back()) > tolerance && distance(p, end) > tolerance)
          rebuilt.push_back(p);
      }
    }
    contours[c] = std::move(rebuilt);
  }
}

} // namespace

std::size_t insertMutualIntersections(std::vector<Polygon2>& lower, std::vector<Polygon2>& upper, double tolerance)
{
  if (lower.empty() || upper.empty())
    return 0;
  const double cellSize = 2.0 * medianEdgeLength(lower, upper);
  const EdgeGrid upperGrid(upper, cellSize, tolerance);

  std::vector<Insertion> intoLower, intoUpper;
  std::size_t crossings = 0;
  // Each candidate pair is tested once: stamp the upper edges already seen for this lower edge.
  std::vector<std::vector<int>> seen(upper.size());
  for (std::size_t c = 0; c < upper.size(); ++c)
    seen[c].assign(upper[c].size(), -1);
  int stamp = 0;
  // The tolerance a hair wider (far above the rounding of a distance at these coordinates), so that
  // no pair the distance tests below would find within it is passed over by the boxes.
  double extent = 0.0;
  for (const std::vector<Polygon2>* slice : { &lower, &upper })
    for (const Polygon2& polygon : *slice)
      for (const Point2& point : polygon)
        extent = std::max({ extent, std::abs(point.x), std::abs(point.y) });
  const double reach = tolerance * (1.0 + 1e-9) + 1e-12 * (cellSize + extent);

  for (int lc = 0; lc < static_cast<int>(lower.size()); ++lc)
  {
    const Polygon2& lp = lower[lc];
    for (int le = 0; le < static_cast<int>(lp.size()); ++le, ++stamp)
    {
      const Point2& p = lp[le];
      const Point2& q = lp[(le + 1) % lp.size()];
      upperGrid.forEachNear(p, q, [&](const EdgeRef& ref) {
        int& mark = seen[ref.contour][ref.edge];
        if (mark == stamp)
          return;
        mark = stamp;
        const Polygon2& up = upper[ref.contour];
        const Point2& r = up[ref.edge];
        const Point2& s = up[(ref.edge + 1) % up.size()];
        // Edges whose boxes, grown by the tolerance, do not overlap can neither touch nor cross:
        // most of the pairs a cell holds.
        if (std::max(p.x, q.x) + reach < std::min(r.x, s.x) || std::max(r.x, s.x) + reach < std::min(p.x, q.x) ||
            std::max(p.y, q.y) + reach < std::min(r.y, s.y) || std::max(r.y, s.y) + reach < std::min(p.y, q.y))
          return;

        double t = 0.0;
        bool touching = false;
        // A vertex of one slice on the inside of the other slice's edge splits that edge.
        for (const Point2* v : { &r, &s })
          if (distanceToSegment(*v, p, q, &t) <= tolerance && distance(*v, p) > tolerance &&
              distance(*v, q) > tolerance)
          {
            intoLower.push_back({ lc, le, t, *v });
            touching = true;
          }
        for (const Point2* v : { &p, &q })
          if (distanceToSegment(*v, r, s, &t) <= tolerance && distance(*v, r) > tolerance &&
              distance(*v, s) > tolerance)
          {
            intoUpper.push_back({ ref.contour, ref.edge, t, *v });
            touching = true;
          }
        if (touching || distanceToSegment(r, p, q) <= tolerance || distanceToSegment(s, p, q) <= tolerance ||
            distanceToSegment(p, r, s) <= tolerance || distanceToSegment(q, r, s) <= tolerance)
          return;
        // A proper crossing becomes a vertex of both slices.
        if (orientation(p, q, r) * orientation(p, q, s) < 0 && orientation(r, s, p) * orientation(r, s, q) < 0)
        {
          const double dx = q.x - p.x, dy = q.y - p.y, ex = s.x - r.x, ey = s.y - r.y;
          const double tl = ((r.x - p.x) * ey - (r.y - p.y) * ex) / (dx * ey - dy * ex);
          const Point2 x{ p.x + tl * dx, p.y + tl * dy };
          double tu = 0.0;
          distanceToSegment(x, r, s, &tu);
          intoLower.push_back({ lc, le, tl, x });
          intoUpper.push_back({ ref.contour, ref.edge, tu, x });
          ++crossings;
        }
      });
    }
  }
  applyInsertions(lower, intoLower, tolerance);
  applyInsertions(upper, intoUpper, tolerance);
  return crossings;
}

std::size_t removeVerticesNearCommonOnes(std::vector<Polygon2>& contours, const std::vector<Polygon2>* below,
                                         const std::vector<Polygon2>* above, double shortLength, double tolerance)
{
  if (!(shortLength > 0.0) || contours.empty())
    return 0;
  // The neighbour slices' points (with their contour) and edges, and the slice's own points as they
  // were (a removed vertex still counts: conservative, and it keeps the hash simple).
  struct NeighbourPoint
  {
    Point2 p;
    int contour;
  };
  std::vector<Polygon2> neighbourContours;
  std::vector<NeighbourPoint> neighbours;
  for (const std::vector<Polygon2>* slice : { below, above })
    if (slice)
      for (const Polygon2& polygon : *slice)
      {
        for (const Point2& p : polygon)
          neighbours.push_back({ p, static_cast<int>(neighbourContours.size()) });
        neighbourContours.push_back(polygon);
      }
  if (neighbours.empty())
    return 0;
  SpatialHash neighbourCells(shortLength);
  for (int i = 0; i < static_cast<int>(neighbours.size()); ++i)
    neighbourCells.insert(neighbours[i].p, i);
  auto isCommon = [&](const Point2& p) {
    return neighbourCells.anyIn(neighbourCells.cellsWithin(p, tolerance),
                                [&](int i) { return distance(neighbours[i].p, p) <= tolerance; });
  };
  // Most slices have no vertex in common with their neighbours (planning-system contours hardly
  // ever do): the rest is built only for those that have.
  if (std::none_of(contours.begin(), contours.end(), [&](const Polygon2& polygon)
                   { return std::any_of(polygon.begin(), polygon.end(), isCommon); }))
    return 0;
  std::vector<Point2> own;
  for (const Polygon2& polygon : contours)
    own.insert(own.end(), polygon.begin(), polygon.end());
  SpatialHash ownCells(shortLength);
  for (int i = 0; i < static_cast<int>(own.size()); ++i)
    ownCells.insert(own[i], i);
  const EdgeGrid neighbourEdges(neighbourContours, 2.0 * shortLength, tolerance);

  // Whether p lies in the closed triangle cba, or within tolerance of its new edge ca.
  auto inCutOff = [&](const Point2& c, const Point2& b, const Point2& a, const Point2& p) {
    if (distanceToSegment(p, c, a) <= tolerance)
      return true;
    const int o = orientation(c, b, a);
    return o != 0 && orientation(c, b, p) * o >= 0 && orientation(b, a, p) * o >= 0 && orientation(a, c, p) * o >= 0;
  };
  // Removing b replaces edges cb and ba by the chord ca. The slices still meet only at common vertices
  // if no neighbour edge meets the chord but at a common end of it; a neighbour contour may then pass
  // into the cut-off corner (through a or c), but not lie in it whole (it would change sides). Own
  // contours cannot cross cb or ba, so one meets the chord only with a point in the corner.
  auto mayRemove = [&](const Point2& c, const Point2& b, const Point2& a, bool cCommon) {
    const Box2 box{ std::min({ a.x, b.x, c.x }) - tolerance, std::min({ a.y, b.y, c.y }) - tolerance,
                    std::max({ a.x, b.x, c.x }) + tolerance, std::max({ a.y, b.y, c.y }) + tolerance };
    const bool ownInside = ownCells.anyIn(ownCells.cellsOf(box), [&](int i) {
      const Point2& p = own[i];
      const bool corner = (p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y) || (p.x == c.x && p.y == c.y);
      return !corner && inCutOff(c, b, a, p);
    });
    if (ownInside)
      return false;
    auto atEnd = [&](const Point2& p) {
      return distance(p, a) <= tolerance || (cCommon && distance(p, c) <= tolerance);
    };
    bool meets = false;
    neighbourEdges.forEachNear(c, a, [&](const EdgeRef& ref) {
      if (meets)
        return;
      const Polygon2& polygon = neighbourContours[ref.contour];
      const Point2& p = polygon[ref.edge];
      const Point2& q = polygon[(ref.edge + 1) % polygon.size()];
      const bool pEnd = atEnd(p), qEnd = atEnd(q);
      if (pEnd && qEnd)
        meets = true; // runs along the chord
      else if (pEnd)
        meets = distanceToSegment(q, c, a) <= tolerance;
      else if (qEnd)
        meets = distanceToSegment(p, c, a) <= tolerance;
      else
        meets = distanceToSegment(p, c, a) <= tolerance || distanceToSegment(q, c, a) <= tolerance ||
                distanceToSegment(c, p, q) <= tolerance || distanceToSegment(a, p, q) <= tolerance ||
                (orientation(c, a, p) * orientation(c, a, q) <= 0 && orientation(p, q, c) * orientation(p, q, a) <= 0);
    });
    if (meets)
      return false;
    // A neighbour contour with a point in the corner must also have one outside it.
    std::vector<int> inside;
    neighbourCells.forEachIn(neighbourCells.cellsOf(box), [&](int i) {
      if (!atEnd(neighbours[i].p) && inCutOff(c, b, a, neighbours[i].p))
        inside.push_back(neighbours[i].contour);
    });
    for (const int contour : inside)
    {
      const Polygon2& polygon = neighbourContours[contour];
      if (std::all_of(polygon.begin(), polygon.end(),
                      [&](const Point2& p) { return atEnd(p) || inCutOff(c, b, a, p); }))
        return false;
    }
    return true;
  };

  std::size_t removed = 0;
  for (Polygon2& polygon : contours)
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      if (!isCommon(polygon[i]))
        continue;
      // Free vertices closer than shortLength on either side, one at a time while the chord that
      // replaces them is no shorter than the edge they end.
      for (const int step : { 1, -1 })
        while (polygon.size() > 8)
        {
          const std::size_t n = polygon.size();
          const std::size_t bi = (i + n + step) % n, ci = (i + n + 2 * step) % n;
          const Point2 a = polygon[i], b = polygon[bi], c = polygon[ci];
          if (distance(a, b) >= shortLength || distance(c, a) < distance(a, b) || isCommon(b) ||
              !mayRemove(c, b, a, isCommon(c)))
            break;
          polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(bi));
          if (bi < i)
            --i;
          ++removed;
        }
    }
  return removed;
}

} // namespace slicemesh

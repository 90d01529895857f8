#include "Correspondence/MutualIntersections.h"

#include "Core/PlanarGeometry.h"
#include "Core/SpatialHash.h"

#include <algorithm>
#include <cmath>

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
  EdgeGrid(const std::vector<Polygon2>& contours, double cellSize, double margin)
    : m_Cells(cellSize)
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
  SpatialHash::CellRange cellsOf(const Point2& a, const Point2& b) const
  {
    return m_Cells.cellsOf({ std::min(a.x, b.x) - m_Margin, std::min(a.y, b.y) - m_Margin,
                             std::max(a.x, b.x) + m_Margin, std::max(a.y, b.y) + m_Margin });
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

} // namespace slicemesh

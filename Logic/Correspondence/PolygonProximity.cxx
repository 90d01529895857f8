#include "Correspondence/PolygonProximity.h"

#include "Core/SpatialHash.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicemesh
{

namespace
{

Box2 edgeBox(const Point2& a, const Point2& b)
{
  return { std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y) };
}

Box2 intersection(const Box2& a, const Box2& b)
{
  return { std::max(a.xmin, b.xmin), std::max(a.ymin, b.ymin), std::min(a.xmax, b.xmax), std::min(a.ymax, b.ymax) };
}

Box2 inflated(const Box2& box, double margin)
{
  return { box.xmin - margin, box.ymin - margin, box.xmax + margin, box.ymax + margin };
}

/** Edges in a spatial hash, each over the part of its box within a region: every point the callers
 *  look for (where two edges touch, or come closest) lies in that region, and edges far longer than
 *  the region take no more cells than the region has. */
class EdgeGrid
{
public:
  EdgeGrid(const Box2& region, double cell)
    : m_Region(region)
    , m_Cells(cell)
  {
  }

  void insert(const Box2& box, std::size_t item)
  {
    if (box.overlaps(m_Region))
      m_Cells.insert(m_Cells.cellsOf(intersection(box, m_Region)), static_cast<int>(item));
  }

  /** Calls visit(item) for each item sharing a cell with box within the region (an item may come more
   *  than once). */
  template <typename Visit>
  void query(const Box2& box, Visit&& visit) const
  {
    if (box.overlaps(m_Region))
      m_Cells.forEachIn(m_Cells.cellsOf(intersection(box, m_Region)),
                        [&](int item) { visit(static_cast<std::size_t>(item)); });
  }

private:
  Box2 m_Region;
  SpatialHash m_Cells;
};

/** Cell size for about one edge per cell over a box holding n edges. */
double cellSizeFor(const Box2& box, std::size_t n)
{
  const double w = std::max(box.xmax - box.xmin, 0.0), h = std::max(box.ymax - box.ymin, 0.0);
  const double size = std::sqrt(std::max(w * h, 1e-300) / static_cast<double>(std::max<std::size_t>(n, 1)));
  return std::max({ size, 1e-3 * std::max(w, h), 1e-9 });
}

/** Parameter of the projection of p onto the line ab (0 at a, 1 at b). */
double parameterOn(const Point2& p, const Point2& a, const Point2& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  return len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
}

/** Whether q, collinear with segment ab, lies on it. */
bool onCollinearSegment(const Point2& q, const Point2& a, const Point2& b)
{
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
         q.y <= std::max(a.y, b.y);
}

/** A point strictly inside the polygon: the middle of the first inside interval of a horizontal line
 *  that passes between vertex heights (so it meets no vertex). */
bool interiorPoint(const Polygon2& polygon, Point2& out)
{
  std::vector<double> ys;
  ys.reserve(polygon.size());
  for (const Point2& p : polygon)
    ys.push_back(p.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  if (ys.size() < 2)
    return false;
  // The widest gap near the middle gives a well-conditioned line.
  std::size_t best = ys.size() / 2 - (ys.size() % 2 == 0 ? 1 : 0);
  for (std::size_t k = ys.size() / 4; k + 1 < ys.size() && k <= 3 * ys.size() / 4; ++k)
    if (ys[k + 1] - ys[k] > ys[best + 1] - ys[best])
      best = k;
  const double y = 0.5 * (ys[best] + ys[best + 1]);
  std::vector<double> xs;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    if ((a.y < y) != (b.y < y))
      xs.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
  }
  if (xs.size() < 2)
    return false;
  std::sort(xs.begin(), xs.end());
  out = { 0.5 * (xs[0] + xs[1]), y };
  return true;
}

double segmentDistance(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1)
{
  const int o1 = orientation(a0, a1, b0), o2 = orientation(a0, a1, b1);
  const int o3 = orientation(b0, b1, a0), o4 = orientation(b0, b1, a1);
  if (o1 * o2 < 0 && o3 * o4 < 0)
    return 0.0;
  return std::min({ distanceToSegment(b0, a0, a1), distanceToSegment(b1, a0, a1), distanceToSegment(a0, b0, b1),
                    distanceToSegment(a1, b0, b1) });
}

} // namespace

IndexedPolygon::IndexedPolygon(const Polygon2& polygon)
  : m_Polygon(polygon)
  , m_Box(boundingBox(polygon))
{
  const std::size_t n = polygon.size();
  if (n == 0)
    return;
  const std::size_t bandCount = std::max<std::size_t>(1, n / 2);
  m_BandHeight = std::max((m_Box.ymax - m_Box.ymin) / static_cast<double>(bandCount), 1e-300);
  m_Bands.resize(bandCount);
  auto band = [&](double y) {
    return std::min(bandCount - 1, static_cast<std::size_t>(std::max(0.0, (y - m_Box.ymin) / m_BandHeight)));
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    for (std::size_t k = band(std::min(a.y, b.y)); k <= band(std::max(a.y, b.y)); ++k)
      m_Bands[k].push_back(i);
  }
}

IndexedPolygon::Location IndexedPolygon::locate(const Point2& p) const
{
  if (m_Bands.empty() || p.x < m_Box.xmin || p.x > m_Box.xmax || p.y < m_Box.ymin || p.y > m_Box.ymax)
    return Location::Outside;
  const std::size_t k = std::min(m_Bands.size() - 1, static_cast<std::size_t>(std::max(0.0, (p.y - m_Box.ymin) / m_BandHeight)));
  // Crossing count of the ray to the right of p with half-open edges [ymin, ymax), every edge that
  // spans p.y being in p's band; a zero orientation on a spanning edge puts p on the boundary.
  const Polygon2& polygon = m_Polygon;
  const std::size_t n = polygon.size();
  int winding = 0;
  for (std::size_t i : m_Bands[k])
  {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    if ((a.x == p.x && a.y == p.y) || (b.x == p.x && b.y == p.y))
      return Location::Boundary;
    if (a.y == p.y && b.y == p.y)
    {
      if (std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x))
        return Location::Boundary;
      continue;
    }
    if (std::min(a.y, b.y) > p.y || std::max(a.y, b.y) < p.y)
      continue;
    const int o = orientation(a, b, p);
    if (o == 0)
      return Location::Boundary;
    if (a.y <= p.y && b.y > p.y && o > 0)
      ++winding;
    else if (b.y <= p.y && a.y > p.y && o < 0)
      --winding;
  }
  return winding != 0 ? Location::Inside : Location::Outside;
}

bool regionsOverlap(const IndexedPolygon& a, const IndexedPolygon& b)
{
  const Polygon2& pa = a.polygon();
  const Polygon2& pb = b.polygon();
  if (pa.size() < 3 || pb.size() < 3 || !a.box().overlaps(b.box()))
    return false;

  // 1. A vertex strictly inside the other region decides at once (the usual case for overlap).
  for (const Point2& p : pa)
    if (b.locate(p) == IndexedPolygon::Location::Inside)
      return true;
  for (const Point2& p : pb)
    if (a.locate(p) == IndexedPolygon::Location::Inside)
      return true;

  // 2. No vertex inside: the regions share area only if the boundaries cross, or touch with a piece
  //    of one boundary running inside the other between contacts, or coincide. Pair the edges in the
  //    common box on a grid and record where they touch.
  const Box2 common = intersection(a.box(), b.box());
  EdgeGrid grid(common, cellSizeFor(common, pa.size() + pb.size()));
  const std::size_t na = pa.size(), nb = pb.size();
  for (std::size_t i = 0; i < na; ++i)
    grid.insert(edgeBox(pa[i], pa[(i + 1) % na]), i);
  std::vector<std::vector<double>> contactsA(na), contactsB(nb);
  bool anyContact = false;
  for (std::size_t j = 0; j < nb; ++j)
  {
    const Point2& b0 = pb[j];
    const Point2& b1 = pb[(j + 1) % nb];
    bool crossing = false;
    grid.query(edgeBox(b0, b1), [&](std::size_t i) {
      const Point2& a0 = pa[i];
      const Point2& a1 = pa[(i + 1) % na];
      if (crossing || !edgeBox(a0, a1).overlaps(edgeBox(b0, b1)))
        return;
      const int o1 = orientation(a0, a1, b0), o2 = orientation(a0, a1, b1);
      const int o3 = orientation(b0, b1, a0), o4 = orientation(b0, b1, a1);
      if (o1 * o2 < 0 && o3 * o4 < 0)
      {
        crossing = true; // a proper crossing: the regions overlap next to it
        return;
      }
      auto touch = [&](const Point2& q, int o, const Point2& s0, const Point2& s1, std::vector<double>& list,
                       double t, std::vector<double>& ownList) {
        if (o == 0 && onCollinearSegment(q, s0, s1))
        {
          list.push_back(parameterOn(q, s0, s1));
          ownList.push_back(t);
          anyContact = true;
        }
      };
      touch(b0, o1, a0, a1, contactsA[i], 0.0, contactsB[j]);
      touch(b1, o2, a0, a1, contactsA[i], 1.0, contactsB[j]);
      touch(a0, o3, b0, b1, contactsB[j], 0.0, contactsA[i]);
      touch(a1, o4, b0, b1, contactsB[j], 1.0, contactsA[i]);
    });
    if (crossing)
      return true;
  }
  if (!anyContact)
    return false; // disjoint boundaries, and no vertex of either inside the other

  // 3. Each piece of a boundary between contacts lies wholly inside or outside the other region; the
  //    pieces holding a vertex were located in step 1, the others are sub-segments between contacts.
  auto subsegmentInside = [](const Polygon2& polygon, std::vector<std::vector<double>>& contacts,
                             const IndexedPolygon& other) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      std::vector<double>& ts = contacts[i];
      if (ts.empty())
        continue;
      ts.push_back(0.0);
      ts.push_back(1.0);
      std::sort(ts.begin(), ts.end());
      const Point2& p0 = polygon[i];
      const Point2& p1 = polygon[(i + 1) % n];
      for (std::size_t k = 0; k + 1 < ts.size(); ++k)
      {
        if (ts[k + 1] <= ts[k])
          continue;
        const double t = 0.5 * (ts[k] + ts[k + 1]);
        const Point2 mid{ p0.x + t * (p1.x - p0.x), p0.y + t * (p1.y - p0.y) };
        if (other.locate(mid) == IndexedPolygon::Location::Inside)
          return true;
      }
    }
    return false;
  };
  if (subsegmentInside(pa, contactsA, b) || subsegmentInside(pb, contactsB, a))
    return true;

  // 4. Every boundary point lies on or outside the other region: the regions are disjoint or equal.
  Point2 inner;
  return interiorPoint(pa, inner) && a.locate(inner) == IndexedPolygon::Location::Inside &&
         b.locate(inner) == IndexedPolygon::Location::Inside;
}

double boundaryDistance(const IndexedPolygon& a, const IndexedPolygon& b, double limit)
{
  const Polygon2& pa = a.polygon();
  const Polygon2& pb = b.polygon();
  const double none = std::numeric_limits<double>::infinity();
  if (pa.size() < 2 || pb.size() < 2 || !(limit >= 0.0) || !a.box().overlaps(b.box(), limit))
    return none;
  // Only edges within limit of the other polygon's box can be that close.
  const Box2 region = intersection(inflated(a.box(), limit), inflated(b.box(), limit));
  const std::size_t na = pa.size(), nb = pb.size();
  EdgeGrid grid(region, std::max(limit, cellSizeFor(region, na + nb)));
  for (std::size_t i = 0; i < na; ++i)
    grid.insert(inflated(edgeBox(pa[i], pa[(i + 1) % na]), limit), i);
  double best = none;
  for (std::size_t j = 0; j < nb; ++j)
  {
    const Point2& b0 = pb[j];
    const Point2& b1 = pb[(j + 1) % nb];
    const Box2 box = edgeBox(b0, b1);
    grid.query(box, [&](std::size_t i) {
      const Point2& a0 = pa[i];
      const Point2& a1 = pa[(i + 1) % na];
      if (!edgeBox(a0, a1).overlaps(box, std::min(limit, best)))
        return;
      best = std::min(best, segmentDistance(a0, a1, b0, b1));
    });
    if (best == 0.0)
      break;
  }
  return best <= limit ? best : none;
}

} // namespace slicemesh

#include "Core/NearestSegment.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicemesh
{

NearestSegment::NearestSegment(std::vector<Segment> segments, double cellSize)
  : m_Segments(std::move(segments))
  , m_Cells(std::max(cellSize, 1e-9))
{
  long long xmin = std::numeric_limits<long long>::max(), xmax = std::numeric_limits<long long>::min();
  long long ymin = xmin, ymax = xmax;
  for (int s = 0; s < static_cast<int>(m_Segments.size()); ++s)
  {
    const auto& [a, b] = m_Segments[s];
    const SpatialHash::CellRange cells =
      m_Cells.cellsOf(Box2{ std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y) });
    m_Cells.insert(cells, s);
    xmin = std::min(xmin, cells.x0);
    xmax = std::max(xmax, cells.x1);
    ymin = std::min(ymin, cells.y0);
    ymax = std::max(ymax, cells.y1);
  }
  if (!m_Segments.empty())
  {
    m_CenterX = (xmin + xmax) / 2;
    m_CenterY = (ymin + ymax) / 2;
    m_Extent = std::max(xmax - xmin, ymax - ymin) + 2;
  }
}

double NearestSegment::search(const Point2& p, Point2* closest, double limit) const
{
  double best = std::numeric_limits<double>::infinity(), bestSquared = best;
  if (m_Segments.empty())
    return best;
  const long long cx = m_Cells.cellOf(p.x), cy = m_Cells.cellOf(p.y);
  // Search square rings of cells outwards; a segment found within ring r is at most
  // (r + 1) cells away, and no segment in a farther ring can be closer than r cells.
  const long long maxRing =
    std::max(std::abs(cx - m_CenterX), std::abs(cy - m_CenterY)) + m_Extent;
  for (long long r = 0; r <= maxRing; ++r)
  {
    // No segment of ring r or beyond is nearer than r - 1 cells: none can beat best, nor come under
    // the limit (if best is not under it, no one is).
    if (best <= (r - 1) * m_Cells.cellSize() || limit < (r - 1) * m_Cells.cellSize())
      break;
    auto visit = [&](long long x, long long y) {
      for (int s : m_Cells.cell(x, y))
      {
        const auto& [a, b] = m_Segments[s];
        double t = 0.0;
        const double squared = squaredDistanceToSegment(p, a, b, &t);
        if (squared > bestSquared)
          continue; // its root is no smaller than best's: the root is taken only where it may be
        const double d = std::sqrt(squared);
        if (d < best)
        {
          best = d;
          bestSquared = squared;
          if (closest)
            *closest = { a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
        }
      }
    };
    if (r == 0)
      visit(cx, cy);
    for (long long i = -r; i < r; ++i) // the ring's four sides, each without its last cell
    {
      visit(cx + i, cy - r);
      visit(cx + r, cy + i);
      visit(cx - i, cy + r);
      visit(cx - r, cy - i);
    }
  }
  return best;
}

} // namespace slicemesh

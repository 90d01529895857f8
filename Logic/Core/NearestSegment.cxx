#include "Core/NearestSegment.h"

#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicemesh
{

NearestSegment::NearestSegment(std::vector<Segment> segments, double cellSize)
  : m_Segments(std::move(segments))
  , m_CellSize(std::max(cellSize, 1e-9))
{
  long long xmin = std::numeric_limits<long long>::max(), xmax = std::numeric_limits<long long>::min();
  long long ymin = xmin, ymax = xmax;
  for (int s = 0; s < static_cast<int>(m_Segments.size()); ++s)
  {
    const auto& [a, b] = m_Segments[s];
    const long long x0 = cellOf(std::min(a.x, b.x)), x1 = cellOf(std::max(a.x, b.x));
    const long long y0 = cellOf(std::min(a.y, b.y)), y1 = cellOf(std::max(a.y, b.y));
    for (long long x = x0; x <= x1; ++x)
      for (long long y = y0; y <= y1; ++y)
        m_Cells[key(x, y)].push_back(s);
    xmin = std::min(xmin, x0);
    xmax = std::max(xmax, x1);
    ymin = std::min(ymin, y0);
    ymax = std::max(ymax, y1);
  }
  if (!m_Segments.empty())
  {
    m_CenterX = (xmin + xmax) / 2;
    m_CenterY = (ymin + ymax) / 2;
    m_Extent = std::max(xmax - xmin, ymax - ymin) + 2;
  }
}

long long NearestSegment::cellOf(double v) const
{
  return static_cast<long long>(std::floor(v / m_CellSize));
}

std::uint64_t NearestSegment::key(long long x, long long y) const
{
  return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
}

double NearestSegment::nearest(const Point2& p, Point2* closest) const
{
  double best = std::numeric_limits<double>::infinity();
  if (m_Segments.empty())
    return best;
  const long long cx = cellOf(p.x), cy = cellOf(p.y);
  // Search square rings of cells outwards; a segment found within ring r is at most
  // (r + 1) cells away, and no segment in a farther ring can be closer than r cells.
  const long long maxRing =
    std::max(std::abs(cx - m_CenterX), std::abs(cy - m_CenterY)) + m_Extent;
  for (long long r = 0; r <= maxRing; ++r)
  {
    if (best <= (r - 1) * m_CellSize)
      break;
    auto visit = [&](long long x, long long y) {
      auto it = m_Cells.find(key(x, y));
      if (it == m_Cells.end())
        return;
      for (int s : it->second)
      {
        const auto& [a, b] = m_Segments[s];
        double t = 0.0;
        const double d = distanceToSegment(p, a, b, &t);
        if (d < best)
        {
          best = d;
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

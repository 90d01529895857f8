// Distance from a point to the nearest of many segments, through a uniform grid.
#ifndef NearestSegment_h
#define NearestSegment_h

#include "Core/SliceMeshTypes.h"

#include <unordered_map>
#include <utility>
#include <vector>

namespace slicemesh
{

class NearestSegment
{
public:
  using Segment = std::pair<Point2, Point2>;

  /** cellSize: about the typical segment length (mm). */
  NearestSegment(std::vector<Segment> segments, double cellSize);

  /** Distance to the nearest segment; +infinity when there is none. */
  double distance(const Point2& p) const { return nearest(p, nullptr); }

  /** Distance to the nearest segment, and the nearest point on it. */
  double nearest(const Point2& p, Point2* closest) const;

  bool empty() const { return m_Segments.empty(); }

private:
  long long cellOf(double v) const;
  std::uint64_t key(long long x, long long y) const;

  std::vector<Segment> m_Segments;
  double m_CellSize;
  long long m_Extent = 0; ///< half-width, in cells, of the square that holds every segment
  long long m_CenterX = 0, m_CenterY = 0;
  std::unordered_map<std::uint64_t, std::vector<int>> m_Cells;
};

} // namespace slicemesh

#endif

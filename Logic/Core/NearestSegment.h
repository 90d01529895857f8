// Distance from a point to the nearest of many segments, through a spatial hash of their boxes.
#ifndef NearestSegment_h
#define NearestSegment_h

#include "Core/SpatialHash.h"

#include <limits>
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
  double nearest(const Point2& p, Point2* closest) const { return search(p, closest, m_Unbounded); }

  /** The distance to the nearest segment where it is under `limit`; otherwise a value not under
   *  `limit` (perhaps not the distance). The search stops at `limit`: a query far from every
   *  segment (the middle of a cap, asked how far its rim is) visits the cells out to it only. */
  double distanceWithin(const Point2& p, double limit) const { return search(p, nullptr, limit); }

  bool empty() const { return m_Segments.empty(); }

private:
  double search(const Point2& p, Point2* closest, double limit) const;

  static constexpr double m_Unbounded = std::numeric_limits<double>::infinity();
  std::vector<Segment> m_Segments;
  SpatialHash m_Cells;
  long long m_Extent = 0; ///< half-width, in cells, of the square that holds every segment
  long long m_CenterX = 0, m_CenterY = 0;
};

} // namespace slicemesh

#endif

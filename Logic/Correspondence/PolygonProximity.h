// Two questions about a pair of closed polygons from adjacent slices, asked in projection:
// do the regions they bound share area, and how close do their boundaries come?
#ifndef PolygonProximity_h
#define PolygonProximity_h

#include "Core/PlanarGeometry.h"

#include <vector>

namespace slicemesh
{

/** A closed polygon (copied) with a y-band index of its edges, for point location in about
 *  O(sqrt n) instead of O(n). */
class IndexedPolygon
{
public:
  explicit IndexedPolygon(const Polygon2& polygon);

  enum class Location
  {
    Outside,
    Boundary,
    Inside
  };
  /** Where p lies (even-odd rule, exact orientation predicates). */
  Location locate(const Point2& p) const;

  const Polygon2& polygon() const { return m_Polygon; }
  const Box2& box() const { return m_Box; }

private:
  Polygon2 m_Polygon;
  Box2 m_Box;
  double m_BandHeight = 1.0;
  std::vector<std::vector<std::size_t>> m_Bands; ///< edge i joins every band its y-range touches
};

/** Whether the regions bounded by a and b share interior area (touching boundaries do not count).
 *  Cheap tests first: bounding boxes, then every vertex located in the other polygon; only when
 *  those do not decide, edges are crossed on a uniform grid over the common box. Exact predicates,
 *  so voxel contours with shared vertices and collinear edges are decided correctly. */
bool regionsOverlap(const IndexedPolygon& a, const IndexedPolygon& b);

/** The smallest distance between the boundaries of a and b when it is at most limit; otherwise a
 *  value greater than limit. Edges are paired on a grid of cells at least limit wide. */
double boundaryDistance(const IndexedPolygon& a, const IndexedPolygon& b, double limit);

} // namespace slicemesh

#endif

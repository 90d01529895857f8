// Where the contours of one slice cross, touch or come close to each other or themselves.
#ifndef ContourCrossings_h
#define ContourCrossings_h

#include "Core/SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

/** One edge of a slice's contours: edge `edge` of contour `contour` joins point edge to edge + 1. */
struct ContourEdge
{
  std::size_t contour = 0;
  std::size_t edge = 0;
};

/** Pairs of edges of the closed contours that share a point (cross, touch or overlap), apart from
 *  two consecutive edges of one contour meeting at their common vertex. Exact predicates; a
 *  sweep over x, so about n log n for contours that are apart. */
std::vector<std::pair<ContourEdge, ContourEdge>> contourCrossings(const std::vector<Polygon2>& contours);

/** Pairs of edges that come within `gap` (mm) of each other: the crossings above, and edges that
 *  pass closer than gap without meeting (a narrow channel, two contours nearly touching).
 *  Consecutive edges of one contour are left out as above. */
std::vector<std::pair<ContourEdge, ContourEdge>> contourEdgesWithin(const std::vector<Polygon2>& contours, double gap);

} // namespace slicemesh

#endif

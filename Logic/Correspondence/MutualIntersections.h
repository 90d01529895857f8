// Stage: make the contours of two adjacent slices meet, in projection, only at shared vertices.
#ifndef MutualIntersections_h
#define MutualIntersections_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Inserts into the contours of two adjacent slices the points where, projected onto one plane,
 *  an edge of one slice crosses or touches an edge of the other: a crossing point goes into both
 *  edges (it becomes a vertex of both slices), a vertex lying on the other slice's edge goes into
 *  that edge. Afterwards the two contour sets meet only at common vertices (within tolerance) and
 *  along common edges. Returns the number of crossing points inserted. */
std::size_t insertMutualIntersections(std::vector<Polygon2>& lower, std::vector<Polygon2>& upper, double tolerance);

/** Once the slices meet only at common vertices: a contour vertex closer than shortLength to a common
 *  vertex of its contour (a crossing point, or a point of a wall) leaves a contour edge that short,
 *  and contour edges are never split afterwards, so its triangles keep their small angles. Such a
 *  vertex is removed if it meets neither neighbour slice, the chord that replaces its two edges meets
 *  the neighbour slices' contours only at its common ends, no contour lies whole in the corner cut
 *  off, and its slice's other points are outside that corner: the slices still meet only at common
 *  vertices and no contour changes sides. A contour keeps at least eight points. below and above
 *  (the slices beneath and over) may be null. Returns the number of vertices removed. */
std::size_t removeVerticesNearCommonOnes(std::vector<Polygon2>& contours, const std::vector<Polygon2>* below,
                                         const std::vector<Polygon2>* above, double shortLength, double tolerance);

} // namespace slicemesh

#endif

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

} // namespace slicemesh

#endif

// Which points lie inside a closed surface: the parity of an upward ray's crossings, decided exactly.
#ifndef PointsInside_h
#define PointsInside_h

#include "Core/SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

/** For each point, 1 if it lies inside the closed surface `surface` (an odd number of its triangles
 *  above the point), 0 if outside. The ray goes up from the point moved by (e, e^2, e^3) for an
 *  infinitesimal e, so it never grazes an edge or a vertex and a point on a triangle's plane is
 *  decided too; every sign is an exact predicate. One pass over the triangles (no tree), each
 *  meeting the points of the cells of a grid of the points that its box covers: linear in the
 *  triangles for points spread over the surface's plan. On up to `threads` threads (0: every core);
 *  the answer does not depend on them. */
std::vector<char> pointsInside(const TriangleMesh& surface, const std::vector<Point3>& points, unsigned int threads = 1);

} // namespace slicemesh

#endif

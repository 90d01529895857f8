// Where a finished piece crosses itself or another piece (the centroids of the crossing triangles),
// and the vertices and triangles near those places: what is kept as tiled, or repaired, there.
// Internal to the finishing: SurfaceFinishing and FinishedPieceRepair.
#ifndef CrossingPlaces_h
#define CrossingPlaces_h

#include "Finishing/SurfaceFinishing.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace slicemesh
{

/** The centroid of triangle t of `mesh`. */
Point3 centroid(const TriangleMesh& mesh, std::size_t t);

/** Where a mesh crosses itself: the centroid of every triangle of a crossing pair. */
std::vector<Point3> crossingPlaces(const TriangleMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& crossings);

/** How far from a place where a remesh crossed the tiled triangles are kept: one target edge, so
 *  that the remeshed triangles around them, an edge long, stay clear of the crossing. No farther:
 *  each tiled triangle kept is one the remesh does not even out, and their narrow angles were most
 *  of what a tract atlas's finished surface had under 30 degrees. */
double keptRadius(const SurfaceFinishingOptions& options);

/** The vertices of `mesh` within `radius` of one of `points` (found through the points' columns of
 *  the plane's spatial hash, then by their distance in 3D). */
std::vector<char> verticesNear(const TriangleMesh& mesh, const std::vector<Point3>& points, double radius);

/** The triangles of `mesh` with a corner within `radius` of one of `points`. */
std::vector<char> trianglesNear(const TriangleMesh& mesh, const std::vector<Point3>& points, double radius);

} // namespace slicemesh

#endif

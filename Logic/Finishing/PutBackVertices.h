// Putting a smoothed piece's vertices back where they were before the smoothing, where it made two
// sheets of the piece cross. Internal to the finishing: SurfaceFinishing and FinishedPieceRepair.
#ifndef PutBackVertices_h
#define PutBackVertices_h

#include "Core/SliceMeshTypes.h"
#include "Measures/MeshValidation.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace slicemesh
{

/** Whether p and q are the same point, coordinate for coordinate: how a vertex is told to be where
 *  it was (put back, or never moved). */
inline bool samePoint(const Point3& p, const Point3& q)
{
  return p.x == q.x && p.y == q.y && p.z == q.z;
}

/** A flag per vertex: whether it is somewhere else in `after` than in `before`. */
std::vector<char> movedVertices(const std::vector<Point3>& before, const std::vector<Point3>& after);

/** Puts back where `unsmoothed` (the mesh's points before smoothing) has them the vertices marked
 *  (a flag per vertex); with `movedBack` (a flag per vertex), flags those that moved. Returns how
 *  many vertices moved back. */
std::size_t unsmooth(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed, const std::vector<char>& marked,
                     std::vector<char>* movedBack = nullptr);

/** Two sheets a voxel apart (a thin gap between gyri, a thin wall) can be smoothed into each other:
 *  there, and only there, the vertices go back to where `unsmoothed` has them (growing rings, three
 *  tries). `validation` and `crossings` are the mesh's (validateMesh), kept up to date. Returns how
 *  many vertices went back. */
std::size_t unsmoothCrossings(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed, MeshValidation& validation,
                              std::vector<std::pair<std::size_t, std::size_t>>& crossings);

} // namespace slicemesh

#endif

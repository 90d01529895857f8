// The few crossings a finished piece still has once its smoothing is put back (the remesh's own
// folds) undone where they are, and the piece brought back to its smoothed and widened shape around
// them, so that a large piece is not remeshed again for a handful of folds. Internal to the
// finishing: SurfaceFinishing's smoothed remesh calls it; the mesh operations are CrossingRepair's.
#ifndef FinishedPieceRepair_h
#define FinishedPieceRepair_h

#include "Finishing/SurfaceFinishing.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace slicemesh
{

/** Whether a piece (its validation) crosses itself in few enough places to be repaired where it
 *  does (repairedLocally), and is a mesh the repair's operations keep valid (sound topology, no
 *  degenerate triangles). */
bool repairableLocally(const MeshValidation& validation);

/** The few crossings left in a finished piece undone where they are (repairCrossingsLocally), the
 *  points put back where the remesh left them given their smoothed places again where that crosses
 *  nothing (resmoothedAfterRepair), then the slivers there widened (widenNarrowTrianglesLocally).
 *  `unsmoothed` and `smoothed` (a point per vertex) are renumbered with the vertices (a moved vertex
 *  has its new point for both); `validation`, `crossings`, `crossedAt` and `unsmoothedVertices` are
 *  the piece's after. Where the repair leaves crossings its own count of them stands in the
 *  validation, and `crossings` is empty: the piece is remeshed around `crossedAt`. `held`: the
 *  vertices on drawn contours (a flag per vertex; empty without), which stay; `resmooth`: whether
 *  the points put back may take their smoothed places again. Returns the operations made. */
std::size_t repairedLocally(TriangleMesh& mesh, MeshValidation& validation,
                            std::vector<std::pair<std::size_t, std::size_t>>& crossings, std::vector<Point3>& crossedAt,
                            const std::vector<char>& held, const SurfaceFinishingOptions& options,
                            std::vector<Point3>& unsmoothed, std::vector<Point3>& smoothed, bool resmooth,
                            std::size_t& unsmoothedVertices);

} // namespace slicemesh

#endif

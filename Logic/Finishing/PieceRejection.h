// The test a finished piece passes to replace its tiled self (or a less finished version of itself):
// a valid surface of the same topology, facing the same way. Internal to the finishing:
// SurfaceFinishing and FinishedPieceRepair.
#ifndef PieceRejection_h
#define PieceRejection_h

#include "Measures/MeshValidation.h"

#include <string>

namespace slicemesh
{

/** Why `candidate` may not replace `tiled`, one connected piece of the tiling; empty when it may:
 *  it must be a closed, manifold, consistently oriented surface without degenerate or crossing
 *  triangles, of the same topology and facing the same way (an inner surface stays inner). */
std::string rejection(const MeshValidation& candidate, const MeshValidation& tiled);

} // namespace slicemesh

#endif

// A finished piece's last narrow triangles flipped or collapsed away where they are. Where a
// structure is about as thin as the remesh's edge (a white-matter tract a voxel or two across), the
// remesh and the smoothing leave needles and caps that neither the relaxation nor the remesh's own
// rules undo. Internal to the finishing: SurfaceFinishing's smoothed remesh calls it; the operations
// are CrossingRepair's.
#ifndef NarrowTriangleWidening_h
#define NarrowTriangleWidening_h

#include "Core/SliceMeshTypes.h"
#include "Measures/MeshValidation.h"

#include <cstddef>
#include <vector>

namespace slicemesh
{

/** The triangles of a valid finished piece with an angle under 30 degrees flipped or collapsed away
 *  where that widens the narrowest angle among the triangles an operation changes and crosses nothing
 *  around (widenNarrowTrianglesLocally); the vertices flagged in `fixed` (a flag per vertex of the
 *  mesh as it is, or empty: none; another size throws) stay as they are. The result replaces the
 *  piece only if it is then a valid surface of the same topology, the triangles that changed tested
 *  against the rest; `validation` is the piece's, before and after. `edgeLength`: the remesh's
 *  target (mm), which bounds the operations. Returns the operations made (0: the piece as it was). */
std::size_t widenNarrowTriangles(TriangleMesh& mesh, MeshValidation& validation, const std::vector<char>& fixed,
                                 double edgeLength);

} // namespace slicemesh

#endif

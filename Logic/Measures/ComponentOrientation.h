// Whether each connected component of a closed surface faces the way its nesting says it must.
#ifndef ComponentOrientation_h
#define ComponentOrientation_h

#include "Core/SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

/** The number of components whose winding disagrees with their nesting. A component inside an even
 *  number of the others (an outer surface, or an island inside a cavity) must enclose a positive
 *  volume; one inside an odd number (the wall of a cavity) a negative one. The mesh must be closed,
 *  manifold and free of crossings (nesting is decided from one vertex of each component). On every
 *  core. */
std::size_t misorientedComponents(const TriangleMesh& mesh);

/** The same for meshes side by side, one closed component each, given their signed volumes; on up to
 *  `threads` threads (0: every core). */
std::size_t misorientedComponents(const std::vector<const TriangleMesh*>& components, const std::vector<double>& volumes,
                                  unsigned int threads = 1);

} // namespace slicemesh

#endif

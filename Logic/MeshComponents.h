// The connected components of a triangle mesh (vertices joined by triangles).
#ifndef MeshComponents_h
#define MeshComponents_h

#include "SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

/** The component of every vertex, numbered 0..count-1 in the order of each component's first
 *  triangle; a vertex in no triangle comes after them, a component of its own. */
std::vector<std::size_t> vertexComponents(const TriangleMesh& mesh, std::size_t& count);

} // namespace slicemesh

#endif

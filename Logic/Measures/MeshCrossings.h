// Where separate meshes meet: the pieces of one surface, finished apart, must not cross each other.
#ifndef MeshCrossings_h
#define MeshCrossings_h

#include "Core/SliceMeshTypes.h"

#include <utility>
#include <vector>

namespace slicemesh
{

/** The pairs of meshes (indices, first < second, in increasing order) some triangles of which
 *  intersect or touch each other, and in `trianglePairs` how many such pairs of triangles there are.
 *  The meshes share no vertices, so any contact counts. Only meshes whose bounding boxes overlap are
 *  compared, and within them only triangles whose boxes overlap (CGAL's box intersection, then exact
 *  triangle tests): far less work than the self-intersection test of the meshes taken together. */
std::vector<std::pair<std::size_t, std::size_t>> crossingMeshes(const std::vector<const TriangleMesh*>& meshes,
                                                                std::size_t& trianglePairs);

} // namespace slicemesh

#endif

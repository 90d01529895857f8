// Where separate meshes meet: the pieces of one surface, finished apart, must not cross each other.
#ifndef MeshCrossings_h
#define MeshCrossings_h

#include "Core/SliceMeshTypes.h"

#include <utility>
#include <vector>

namespace slicemesh
{

/** One triangle of one of several meshes: indices into the list of meshes and into its triangles. */
struct MeshTriangle
{
  std::size_t mesh = 0;
  std::size_t triangle = 0;
  bool operator==(const MeshTriangle& other) const { return mesh == other.mesh && triangle == other.triangle; }
  bool operator<(const MeshTriangle& other) const
  {
    return mesh != other.mesh ? mesh < other.mesh : triangle < other.triangle;
  }
};

/** Two triangles of different meshes that meet. */
using TrianglePair = std::pair<MeshTriangle, MeshTriangle>;

/** The pairs of triangles of different meshes that intersect or touch each other, the triangle of
 *  the lower mesh first, in increasing order. The meshes share no vertices, so any contact counts.
 *  Only meshes whose bounding boxes overlap are compared, pair by pair on up to `threads` threads
 *  (0: every core), and within a pair only triangles in the overlap of the two boxes whose own
 *  boxes overlap (CGAL's box intersection, then exact triangle tests): far less work than the
 *  self-intersection test of the meshes taken together. */
std::vector<TrianglePair> crossingTriangles(const std::vector<const TriangleMesh*>& meshes, unsigned int threads = 1);

} // namespace slicemesh

#endif

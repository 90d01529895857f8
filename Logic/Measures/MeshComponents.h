// The connected components of a triangle mesh (vertices joined by triangles).
#ifndef MeshComponents_h
#define MeshComponents_h

#include "Core/SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

/** The component of every vertex, numbered 0..count-1 in the order of each component's first
 *  triangle; a vertex in no triangle comes after them, a component of its own. */
std::vector<std::size_t> vertexComponents(const TriangleMesh& mesh, std::size_t& count);

/** Grows `marked` (one flag per vertex) by `rings` rings of triangles: each ring marks every corner
 *  of a triangle that has a marked corner. */
void growByRings(const TriangleMesh& mesh, std::vector<char>& marked, int rings);

/** The connected pieces of a mesh (by shared vertices), in the order of their first triangle, each
 *  with its triangles in their order and its vertices numbered in theirs: a mesh of one piece comes
 *  back as it was. Vertices in no triangle are left out. */
std::vector<TriangleMesh> splitIntoPieces(const TriangleMesh& mesh);

/** `mesh` appended to `joined`, side by side (its vertices renumbered after joined's, none shared). */
void appendMesh(TriangleMesh& joined, const TriangleMesh& mesh);

/** Where a mesh appended to another begins in it: its first point and first triangle. */
struct AppendedAt
{
  std::size_t point = 0;
  std::size_t triangle = 0;
};

/** What appendMesh added to `joined` between `from` and `to` (where the next one began), numbered
 *  from 0 again: the mesh as it was appended. */
TriangleMesh appendedPart(const TriangleMesh& joined, AppendedAt from, AppendedAt to);

/** The meshes side by side in one mesh, in their order (vertices renumbered, none shared); if
 *  `firstTriangle` is given, (*firstTriangle)[i] is where mesh i's triangles start. */
TriangleMesh joinMeshes(const std::vector<const TriangleMesh*>& meshes,
                        std::vector<std::size_t>* firstTriangle = nullptr);

} // namespace slicemesh

#endif

// A triangle mesh as CGAL's Surface_mesh, for the steps that hand a mesh to CGAL (the
// self-intersection test, inside/outside queries, remeshing). Internal: CGAL stays out of the
// installed headers.
#ifndef SurfaceMeshConversion_h
#define SurfaceMeshConversion_h

#include "Core/SliceMeshTypes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace slicemesh
{

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalSurfaceMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

/** Adds the mesh to an empty `surface`, its vertices and faces numbered as the mesh's points and
 *  triangles. Returns the index of the first triangle that does not fit a manifold surface (the
 *  surface then holds the triangles before it), or the number of triangles when all fit. */
inline std::size_t toSurfaceMesh(const TriangleMesh& mesh, CgalSurfaceMesh& surface)
{
  surface.reserve(mesh.points.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
  std::vector<CgalSurfaceMesh::Vertex_index> vertices;
  vertices.reserve(mesh.points.size());
  for (const Point3& p : mesh.points)
    vertices.push_back(surface.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z)));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
  {
    const Triangle& t = mesh.triangles[i];
    if (surface.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == CgalSurfaceMesh::null_face())
      return i;
  }
  return mesh.triangles.size();
}

} // namespace slicemesh

#endif

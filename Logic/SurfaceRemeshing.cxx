#include "SurfaceRemeshing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <string>

namespace slicemesh
{
namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

SurfaceMesh toSurfaceMesh(const TriangleMesh& mesh)
{
  SurfaceMesh surface;
  surface.reserve(mesh.points.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve(mesh.points.size());
  for (const Point3& p : mesh.points)
    vertices.push_back(surface.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
  {
    const Triangle& t = mesh.triangles[i];
    if (surface.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == SurfaceMesh::null_face())
      throw Error("surface remeshing: triangle " + std::to_string(i) + " does not fit a manifold surface");
  }
  return surface;
}

TriangleMesh toTriangleMesh(SurfaceMesh& surface)
{
  surface.collect_garbage();
  TriangleMesh mesh;
  mesh.points.reserve(surface.number_of_vertices());
  for (SurfaceMesh::Vertex_index v : surface.vertices())
  {
    const Kernel::Point_3& p = surface.point(v);
    mesh.points.push_back({ p.x(), p.y(), p.z() });
  }
  mesh.triangles.reserve(surface.number_of_faces());
  for (SurfaceMesh::Face_index f : surface.faces())
  {
    Triangle triangle{};
    int corner = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      triangle[corner++] = static_cast<std::int32_t>(v.idx());
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

} // namespace

TriangleMesh remeshSurface(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options)
{
  if (!(options.targetEdgeLength > 0.0) || !std::isfinite(options.targetEdgeLength))
    throw Error("surface remeshing: the target edge length must be positive");
  if (options.iterations <= 0 || mesh.triangles.empty())
    return mesh;
  SurfaceMesh surface = toSurfaceMesh(mesh);
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
    faces(surface), options.targetEdgeLength, surface,
    CGAL::parameters::number_of_iterations(static_cast<unsigned int>(options.iterations)));
  return toTriangleMesh(surface);
}

double voxelFaceEdgeLength(const std::array<double, 3>& spacing)
{
  const double sx = spacing[0], sy = spacing[1], sz = spacing[2];
  if (!(sx > 0.0 && sy > 0.0 && sz > 0.0))
    throw Error("surface remeshing: the voxel spacing must be positive");
  return std::sqrt(3.0 / (1.0 / (sx * sy) + 1.0 / (sx * sz) + 1.0 / (sy * sz)));
}

double automaticEdgeLength(const std::array<double, 3>& spacing)
{
  return 1.1 * voxelFaceEdgeLength(spacing);
}

} // namespace slicemesh

#include "Finishing/SurfaceRemeshing.h"

#include "Core/ParallelFor.h"
#include "Measures/MeshComponents.h"
#include "Measures/SurfaceMeshConversion.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace slicemesh
{
namespace
{

using Kernel = CgalKernel;
using SurfaceMesh = CgalSurfaceMesh;
using Vertex = SurfaceMesh::Vertex_index;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh surfaceOf(const TriangleMesh& mesh)
{
  SurfaceMesh surface;
  const std::size_t misfit = toSurfaceMesh(mesh, surface);
  if (misfit != mesh.triangles.size())
    throw Error("surface remeshing: triangle " + std::to_string(misfit) + " does not fit a manifold surface");
  return surface;
}

TriangleMesh toTriangleMesh(SurfaceMesh& surface)
{
  surface.collect_garbage();
  TriangleMesh mesh;
  mesh.points.reserve(surface.number_of_vertices());
  for (Vertex v : surface.vertices())
  {
    const Kernel::Point_3& p = surface.point(v);
    mesh.points.push_back({ p.x(), p.y(), p.z() });
  }
  mesh.triangles.reserve(surface.number_of_faces());
  for (SurfaceMesh::Face_index f : surface.faces())
  {
    Triangle triangle{};
    int corner = 0;
    for (Vertex v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      triangle[corner++] = static_cast<std::int32_t>(v.idx());
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

/** Whether the triangles around v are unfolded: every two consecutive ones with area face the same
 *  side (positive dot product of their normals), and at least one has area. */
bool unfoldedAround(Vertex v, const SurfaceMesh& surface)
{
  Kernel::Vector_3 first = CGAL::NULL_VECTOR, previous = CGAL::NULL_VECTOR;
  bool any = false;
  for (SurfaceMesh::Halfedge_index h : CGAL::halfedges_around_target(v, surface))
  {
    if (surface.is_border(h))
      continue;
    const Kernel::Vector_3 n = PMP::compute_face_normal(surface.face(h), surface);
    if (n == CGAL::NULL_VECTOR)
      continue; // no area, no direction
    if (!any)
      first = n;
    else if (n * previous <= 0.0)
      return false;
    previous = n;
    any = true;
  }
  // A vertex all of whose triangles lost their area cannot be judged: its move is refused. (This is
  // the case that makes CGAL 5.5's own relaxation step read a null halfedge, CGAL issue 7345.)
  return any && first * previous > 0.0;
}

/** One tangential relaxation sweep (Botsch and Kobbelt): every vertex goes towards the centroid of
 *  its neighbours, within its tangent plane. Targets are computed first, then applied one vertex
 *  at a time; a move that folds the triangles around its vertex is halved (five times at most) and
 *  otherwise dropped. This is the step isotropic_remeshing runs itself, done here because CGAL
 *  5.5's version dereferences a null halfedge when every triangle around a moved vertex is
 *  degenerate, which thresholded MRI reaches. */
void relaxTangentially(SurfaceMesh& surface, unsigned int threads)
{
  // Vertex indices are dense here (the caller collected the garbage); every vertex's normal and
  // target is its own, computed from the unmoved surface, so the ranges run side by side.
  const std::size_t vertexCount = surface.number_of_vertices();
  auto [faceNormals, facesCreated] = surface.add_property_map<SurfaceMesh::Face_index, Kernel::Vector_3>("f:relaxation_normal");
  parallelForRanges(surface.number_of_faces(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t f = first; f < last; ++f)
                        faceNormals[SurfaceMesh::Face_index(f)] =
                          PMP::compute_face_normal(SurfaceMesh::Face_index(f), surface);
                    });
  std::vector<std::optional<Kernel::Point_3>> targets(vertexCount);
  parallelForRanges(vertexCount, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t index = first; index < last; ++index)
                      {
                        const Vertex v(static_cast<SurfaceMesh::size_type>(index));
                        if (surface.is_isolated(v) || surface.is_border(v))
                          continue;
                        const Kernel::Vector_3 n =
                          PMP::compute_vertex_normal(v, surface, CGAL::parameters::face_normal_map(faceNormals));
                        const Kernel::Point_3& p = surface.point(v);
                        Kernel::Vector_3 toCentroid = CGAL::NULL_VECTOR;
                        int neighbours = 0;
                        for (Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface))
                        {
                          toCentroid = toCentroid + Kernel::Vector_3(p, surface.point(u));
                          ++neighbours;
                        }
                        const Kernel::Point_3 centroid = p + toCentroid / static_cast<double>(neighbours);
                        targets[index] = centroid + (n * Kernel::Vector_3(centroid, p)) * n;
                      }
                    });
  surface.remove_property_map(faceNormals);
  // Applied one vertex at a time, in order: each fold test sees the moves before it.
  for (std::size_t index = 0; index < vertexCount; ++index)
  {
    if (!targets[index])
      continue;
    const Vertex v(static_cast<SurfaceMesh::size_type>(index));
    const Kernel::Point_3 initial = surface.point(v);
    const Kernel::Vector_3 move(initial, *targets[index]);
    surface.point(v) = *targets[index];
    double fraction = 1.0;
    while (fraction > 0.03 && !unfoldedAround(v, surface))
    {
      fraction *= 0.5;
      surface.point(v) = initial + fraction * move;
    }
    if (fraction <= 0.02)
      surface.point(v) = initial;
  }
}

/** Stands in for CGAL's projection onto the input, which is done separately (remeshPiece). */
struct NoProjection
{
  Kernel::Point_3 operator()(Vertex) const { return CGAL::ORIGIN; }
};

/** Remeshes one connected, closed piece: per round, CGAL's split, collapse and flip, then our own
 *  relaxation sweep and the projection of every vertex onto the input piece. */
TriangleMesh remeshPiece(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options, unsigned int threads)
{
  SurfaceMesh surface = surfaceOf(mesh);
  const SurfaceMesh input = surface;
  Tree tree(faces(input).first, faces(input).second, input);
  tree.accelerate_distance_queries();
  tree.build(); // before the queries run side by side
  for (int round = 0; round < options.iterations; ++round)
  {
    PMP::isotropic_remeshing(faces(surface), options.targetEdgeLength, surface,
                             CGAL::parameters::number_of_iterations(1)
                               .number_of_relaxation_steps(0)
                               .do_project(false)
                               .projection_functor(NoProjection()));
    surface.collect_garbage(); // the next round's face index map must be dense
    relaxTangentially(surface, threads);
    parallelForRanges(surface.number_of_vertices(), threads,
                      [&](std::size_t first, std::size_t last)
                      {
                        for (std::size_t index = first; index < last; ++index)
                        {
                          const Vertex v(static_cast<SurfaceMesh::size_type>(index));
                          surface.point(v) = tree.closest_point(surface.point(v));
                        }
                      });
  }
  return toTriangleMesh(surface);
}

} // namespace

TriangleMesh remeshSurface(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options, unsigned int threads)
{
  if (!(options.targetEdgeLength > 0.0) || !std::isfinite(options.targetEdgeLength))
    throw Error("surface remeshing: the target edge length must be positive");
  if (options.iterations <= 0 || mesh.triangles.empty())
    return mesh;
  // Piece by piece: each vertex is projected back onto its own piece, never onto a neighbour.
  std::vector<TriangleMesh> pieces = splitIntoPieces(mesh);
  for (TriangleMesh& piece : pieces)
    piece = remeshPiece(piece, options, threads);
  if (pieces.size() == 1)
    return std::move(pieces.front());
  std::vector<const TriangleMesh*> remeshed;
  for (const TriangleMesh& piece : pieces)
    remeshed.push_back(&piece);
  return joinMeshes(remeshed);
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

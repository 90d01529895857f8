// Isotropic remeshing of a closed triangle mesh to a target edge length (CGAL).
#ifndef SurfaceRemeshing_h
#define SurfaceRemeshing_h

#include "Core/SliceMeshTypes.h"

#include <array>
#include <vector>

namespace slicemesh
{

struct SurfaceRemeshingOptions
{
  double targetEdgeLength = 1.0; ///< mm
  int iterations = 3;            ///< rounds of split, collapse, flip and relax; one projection after them
  /** Project onto the input after every round, not only the last: for a piece about an edge across
   *  (a speck), which curves away within an edge, so that a round's relaxation leaves it. */
  bool projectEachRound = false;
  /** A piece of at least twice this many triangles is remeshed in slabs of about this many, side by
   *  side, then in bands around their seams; 0: always whole. Small enough for a slab's remesh to
   *  work mostly in the processor's cache (the thick-slice ellipsoid's slabs took 0.6 s at 20,000
   *  against 0.9-1.2 s at 40,000 on two threads), and for the slabs in work side by side to hold
   *  little memory: a slab is held in CGAL's surface mesh while it is remeshed, several hundred bytes
   *  a triangle (with CGAL's own remesher, a 128^3 sphere peaked at 73 MB with slabs of 20,000, at 59
   *  with slabs of 10,000, in the same time). */
  std::size_t trianglesPerRegion = 10000;
  /** The voxel spacing of the grid the surface was traced on (x, y, slice; mm), when the target edge
   *  was set for it (automaticEdgeLength): then each piece the finishing remeshes gets that edge
   *  scaled by how the piece faces the grid (facingEdgeLength over voxelFaceEdgeLength). All 0: the
   *  target edge as it is, for every piece. */
  std::array<double, 3> gridSpacing{ 0.0, 0.0, 0.0 };
};

/** Remeshes the surface with triangles whose edges are close to the target length: long edges
 *  split, short ones collapsed, edges flipped towards valence 6, vertices relaxed tangentially, then
 *  projected back onto the input surface (Botsch and Kobbelt's method, by the rules of CGAL's
 *  Polygon_mesh_processing::isotropic_remeshing). The topology is kept. Throws Error if the mesh is
 *  not a manifold surface CGAL can hold. The relaxation's targets and the projection run on `threads`
 *  threads (0: every core), vertex by vertex, so the result does not depend on the number. With
 *  `heldContours`, the mesh's edges along them (HeldContourEdges.h) are neither split, collapsed nor
 *  flipped and their vertices not moved: the remesh cannot cut across a drawn corner or slot. */
TriangleMesh remeshSurface(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options, unsigned int threads = 1,
                           const ContourStack* heldContours = nullptr);

/** remeshSurface of one connected piece, except that the triangles flagged in `keep` (one flag per
 *  triangle) stay as they are, with their vertices; the rest is remeshed around them, its border
 *  with them kept exactly. For a piece whose remesh crosses itself where two sheets are closer than
 *  an edge: there the input's triangles are kept. Throws Error as remeshSurface does, and if the
 *  triangles not kept do not fit a manifold surface (two of them meeting at a vertex only). */
TriangleMesh remeshSurfaceAround(const TriangleMesh& mesh, const std::vector<char>& keep,
                                 const SurfaceRemeshingOptions& options, unsigned int threads = 1,
                                 const ContourStack* heldContours = nullptr);

/** The edge length at which an isotropic remesh has about as many triangles as flying edges makes on
 *  a grid of this spacing (mm): sqrt(3 / (1/(sx sy) + 1/(sx sz) + 1/(sy sz))), the spacing itself
 *  on an isotropic grid. Flying edges puts a vertex on every grid edge the surface crosses and makes
 *  about two triangles per vertex: on a surface of area A whose normals point every way, about
 *  A (1/(sx sy) + 1/(sx sz) + 1/(sy sz)) triangles. A remesh at edge length L has about 3 A / L^2. */
double voxelFaceEdgeLength(const std::array<double, 3>& spacing);

/** The edge length at which an isotropic remesh of `surface` has about as many triangles as flying
 *  edges makes of it on a grid of this spacing (mm). Flying edges puts a vertex on every grid edge
 *  the surface crosses: along axis i, one per s_j s_k of the surface's area projected along i,
 *  which is the integral of |n_i| over the surface. So a tube along thick slices (its normals in the
 *  slice plane) crosses only the long voxels' side faces and gets few vertices, a cap across them
 *  many. voxelFaceEdgeLength(spacing) for a surface whose normals point every way evenly; 0 for a
 *  surface without area. */
double facingEdgeLength(const TriangleMesh& surface, const std::array<double, 3>& spacing);

/** The default target edge length for a mask of this spacing: 1.1 voxelFaceEdgeLength, so that a
 *  remeshed surface has fewer triangles than Slicer's flying edges on the same grid (about 0.8 of
 *  them), with edges still short enough to follow the mask's detail. */
double automaticEdgeLength(const std::array<double, 3>& spacing);

} // namespace slicemesh

#endif

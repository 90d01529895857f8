// The split, collapse and flip passes of isotropic remeshing (Botsch and Kobbelt, "A remeshing
// approach to multiresolution modeling", 2004), on CGAL's surface mesh. Internal to the finishing:
// SurfaceRemeshing runs a round of them, then its own relaxation and projection.
#ifndef RemeshingPasses_h
#define RemeshingPasses_h

#include "Measures/SurfaceMeshConversion.h"

namespace slicemesh
{

using ConstrainedEdges = CgalSurfaceMesh::Property_map<CgalSurfaceMesh::Edge_index, bool>;
using VertexFlags = CgalSurfaceMesh::Property_map<CgalSurfaceMesh::Vertex_index, bool>;

/** The vertices of drawn contours (HeldContourEdges), whose edges are constrained. */
struct ContourVertices
{
  /** On a contour. No collapse or flip makes a triangle of three of them in one slice plane: it
   *  would lie flat on the slice (a cap pressed onto its contour). */
  VertexFlags onContour;
  /** On the straight line between its two neighbours along the contour (HeldContourEdges::straight):
   *  it may merge into one of them along the line. */
  VertexFlags sliding;
};

/** Twice the area times the unit normal of the triangle of h (h not a border halfedge): the cross
 *  product of its edges from h's source. Enough wherever only the sign of a dot product matters. */
CgalKernel::Vector_3 areaNormal(const CgalSurfaceMesh& mesh, CgalSurfaceMesh::Halfedge_index h);

/** One round over every face of `surface`: edges longer than 4/3 of `targetEdgeLength` split at
 *  their middle, longest first; edges shorter than 4/5 collapsed, shortest first, into one of their
 *  ends where no triangle turns over or loses its area, the link condition holds and no edge grows
 *  past 4/3; edges flipped where that brings the four vertices' valences closer to 6 (or a
 *  triangle of the two is a needle or a cap) and no triangle around turns over. Edges flagged in
 *  `constrained` are neither split, collapsed nor flipped, and a vertex on one is never removed;
 *  except that with `contour`, a short constrained edge from a sliding vertex is collapsed into its
 *  other end, which leaves the contour as it was (a crossing point the tiling put on a contour
 *  edge), and edges that are not locally Delaunay are flipped after the valence flips.
 *
 *  The rules are those of CGAL's isotropic_remeshing, whose round spent most of its time on its own
 *  bookkeeping (ordered containers of edges, a status per halfedge, exact predicates on every edge
 *  for needles and caps); here the edges wait in binary heaps, and an entry whose edge changed
 *  length since is skipped. Leaves removed elements in the mesh (collect_garbage). */
void splitCollapseFlip(CgalSurfaceMesh& surface, const ConstrainedEdges& constrained, double targetEdgeLength,
                       const ContourVertices* contour = nullptr);

} // namespace slicemesh

#endif

// The Dirichlet energy of the tiling's height fields, and whether an edge flip could lower it.
#ifndef DirichletEnergy_h
#define DirichletEnergy_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Between two slices the tiling is a height field z(x, y) over the difference polygons, linear on
 *  each triangle; its Dirichlet energy is the integral of |grad z|^2 over the projected triangles
 *  (for one triangle: projected area times |grad z|^2, in mm^2). Rippa's theorem (S. Rippa,
 *  "Minimal roughness property of the Delaunay triangulation", CAGD 7, 1990) says the Delaunay
 *  triangulation of fixed points minimises it, and a constrained Delaunay one does so among the
 *  triangulations with the same constraints: so no legal flip can lower it. */
struct DirichletEnergy
{
  double energy = 0.0;              ///< sum over the sloped tiling triangles (mm^2)
  std::size_t tilingTriangles = 0;  ///< sloped triangles within a slab (neither vertical nor flat)
  std::size_t flipCandidates = 0;   ///< interior edges a legal flip could replace (see below)
  std::size_t loweringFlips = 0;    ///< candidates whose flip lowers the energy
  double largestDecrease = 0.0;     ///< the largest such decrease (mm^2)
  double largestRelativeDecrease = 0.0; ///< ... relative to the two triangles' energy
};

/** Recomputes the tiling's height fields from the output mesh (in the stack frame) and the
 *  contour stack it was built from. A triangle belongs to slab k when all its vertices lie within
 *  [z_k, z_k+1] of two consecutive slices; it is sloped when its vertices are not all at one
 *  height and its projection onto the slice plane is not degenerate (walls are vertical, caps and
 *  flat chord triangles level). An edge is a flip candidate when its two triangles are sloped
 *  triangles of the same slab that face the same way in projection, the edge is not a contour edge
 *  (a constraint: level at a slice's height, since the tiling splits every other chord between two
 *  points of one slice), the quadrilateral the two triangles form is strictly
 *  convex in projection, and its other diagonal is not already an edge. A flip lowers the energy
 *  when the energy of the two new triangles is below that of the old ones by more than
 *  `relativeTolerance` of it (cocircular quads tie). */
DirichletEnergy measureDirichletEnergy(const TriangleMesh& stackMesh, const ContourStack& stack,
                                       double relativeTolerance = 1e-9);

} // namespace slicemesh

#endif

// Shape quality of a triangle mesh's triangles: angles and aspect ratios.
#ifndef MeshQuality_h
#define MeshQuality_h

#include "Measures/MeshValidation.h"
#include "Core/SliceMeshTypes.h"

#include <vector>

namespace slicemesh
{

struct MeshQuality
{
  std::size_t triangles = 0;
  double minAngleDegrees = 0.0;       ///< smallest angle of any triangle
  double maxAngleDegrees = 0.0;       ///< largest angle of any triangle
  double fractionBelow30 = 0.0;       ///< fraction of triangles with an angle under 30 degrees
  double fractionBelow10 = 0.0;       ///< fraction of triangles with an angle under 10 degrees
  /** Aspect ratio R / (2 r) (circumradius over twice the inradius): 1 for an equilateral triangle,
   *  growing without bound as a triangle degenerates (infinite for a zero-area one). */
  double meanAspectRatio = 0.0;
  double medianAspectRatio = 0.0;
  double p95AspectRatio = 0.0;        ///< 95th percentile
  double maxAspectRatio = 0.0;
};

/** Angles and aspect ratios of the mesh's 3D triangles, measured on `threads` threads (the same
 *  result on any number). */
MeshQuality measureMeshQuality(const TriangleMesh& mesh, unsigned int threads = 1);

/** The smallest angle of each triangle, in degrees (0 for a degenerate one). */
std::vector<double> triangleMinAngles(const TriangleMesh& mesh);

/** Genus of a closed 2-manifold mesh from its Euler characteristic: the sum over its components,
 *  (2 components - chi) / 2; -1 when the mesh is not a closed manifold (genus undefined). */
long genusOf(const MeshValidation& validation);

} // namespace slicemesh

#endif

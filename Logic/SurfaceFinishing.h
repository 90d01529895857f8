// The finishing stage after the tiling: 3D smoothing and isotropic remeshing, kept only when the
// result is still a valid surface of the same topology.
#ifndef SurfaceFinishing_h
#define SurfaceFinishing_h

#include "MeshValidation.h"
#include "SurfaceRemeshing.h"
#include "SurfaceSmoothing.h"

#include <string>

namespace slicemesh
{

/** How far the tiling is finished. */
enum class SurfaceFinish
{
  Remeshed, ///< remeshed to the target edge length, then smoothed in 3D (the default)
  Smoothed, ///< smoothed in 3D; the tiling's triangles kept
  Tiled     ///< the tiling as it is (the paper's surface: every vertex on its slice)
};

struct SurfaceFinishingOptions
{
  SurfaceFinish finish = SurfaceFinish::Remeshed;
  SurfaceSmoothingOptions smoothing;
  SurfaceRemeshingOptions remeshing;
};

struct FinishedSurface
{
  TriangleMesh mesh;
  MeshValidation validation; ///< of `mesh`
  SurfaceFinish finish = SurfaceFinish::Tiled; ///< what was applied (less than asked after a fallback)
  std::string fallback; ///< why less was applied than asked; empty when all of it was
  /** Vertices of the remeshed surface left where the remesh put them, unsmoothed, because smoothing
   *  made triangles near them cross (two sheets of a structure a voxel or two apart). */
  std::size_t unsmoothedVertices = 0;
};

/** The finishing the CLI applies to a mask of this voxel spacing (mm): edges of
 *  automaticEdgeLength(spacing), and smoothing that moves no vertex farther than 0.3 of the smallest
 *  voxel side (the staircase is about that deep; a sharp edge is rounded no more). */
SurfaceFinishingOptions finishingOptionsFor(const std::array<double, 3>& spacing);

/** Finishes a tiling whose validation is given. Where smoothing the remeshed surface makes triangles
 *  cross, the vertices around them (growing rings, up to three tries) go back to their remeshed
 *  positions. A finished mesh is kept only if it is valid and has the tiling's components and Euler
 *  characteristic; otherwise the smoothed tiling is tried, then
 *  the tiling itself is returned, and `fallback` says why. An invalid tiling is returned as it is. */
FinishedSurface finishSurface(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                              const SurfaceFinishingOptions& options);

/** "Remeshed", "Smoothed", "Tiled". */
const char* finishName(SurfaceFinish finish);

} // namespace slicemesh

#endif

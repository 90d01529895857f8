// The options and statistics of the tiling (SurfaceReconstruction.h), apart so that the slab tiling
// it calls can use them without including its caller.
#ifndef TilingOptions_h
#define TilingOptions_h

#include "Core/SliceMeshTypes.h"

#include <functional>

namespace slicemesh
{

enum class CapPlacement
{
  HalfSliceBeyond, ///< caps half a slice beyond the last contour, where the voxels end (default)
  AtSlice          ///< caps flat on the last contour's own slice
};

struct ReconstructionOptions
{
  CapPlacement capPlacement = CapPlacement::HalfSliceBeyond;
  /** Vertical walls (coincident contours, cap rims) are cut into rows about this tall, in mm;
   *  0 means: the median in-plane edge length of the stack, so wall triangles are well shaped. */
  double wallRowHeight = 0.0;
  /** Steiner refinement: the smallest angle wanted in the 3D triangles (degrees); 0 turns it off. */
  double minAngleDegrees = 30.0;
  /** Steiner refinement: target edge length in mm; 0 means the wall row height (itself the median
   *  contour edge length unless given). */
  double maxEdgeLength = 0.0;
  /** Keep the tiling the paper's planar constrained Delaunay triangulation of all its points, which
   *  minimises the Dirichlet energy of the height field (Rippa). Off by default: then edges are also
   *  flipped towards the largest smallest angle of the lifted 3D triangles, which planar Delaunay
   *  cannot give where the surface climbs steeply between nearly parallel contours. */
  bool planarTiling = false;
  /** A contour vertex closer to a crossing point (or another vertex its slice shares with a neighbour)
   *  than this fraction of the median contour edge is removed, where that changes no contour's
   *  crossings, rather than leave a short contour edge (MutualIntersections.h); 0 keeps them all. */
  double shortEdgeFraction = 0.3;
  /** Points of the same slice closer than this (mm) are one point; more for contours whose
   *  coordinates were rounded (mergeToleranceFor). */
  double mergeTolerance = 1e-6;
  /** Threads to tile slabs side by side (0: every core); the mesh does not depend on it. */
  unsigned int threads = 1;
  /** Called with a fraction 0..1 as slabs are tiled; may be empty. */
  std::function<void(double)> progress;
};

struct ReconstructionStatistics
{
  std::size_t slabs = 0;
  std::size_t crossingPoints = 0;   ///< points where a contour crosses its neighbour's contour
  std::size_t verticesRemoved = 0;  ///< contour vertices removed next to crossing points
  std::size_t steinerPoints = 0;    ///< interior points inserted to lift flat chords
  std::size_t wallTriangles = 0;    ///< triangles on vertical walls (coincident contours, cap rims)
  std::size_t capTriangles = 0;     ///< triangles closing the ends of components
  std::size_t tilingTriangles = 0;  ///< triangles over difference polygons
  double wallRowHeight = 0.0;       ///< as used (mm): the option, or its automatic value
  double steinerSpacing = 0.0;      ///< as used (mm): maxEdgeLength, or the wall row height
};

} // namespace slicemesh

#endif

// Every option of the meshing path, and the one place where "0 = automatic" becomes a value.
#ifndef MeshingOptions_h
#define MeshingOptions_h

#include "Contours/ContourPreparation.h"
#include "Finishing/SurfaceFinishing.h"
#include "Sections/IntermediateSections.h"
#include "Tiling/SurfaceReconstruction.h"

#include <array>

namespace slicemesh
{

/** The options of meshContours, stage by stage. A 0 marked "automatic" is resolved from the grid by
 *  resolvedMeshingOptions; the tiling's wall row height and Steiner spacing depend on the contours
 *  themselves and are resolved by the tiling (ReconstructionStatistics reports the values used). */
struct MeshingOptions
{
  ContourPreparationOptions contours;
  UndersamplingOptions undersampling;  ///< correspondence by distance, bridging, sections (all off by default)
  ReconstructionOptions reconstruction;
  /** Remeshed and smoothed by default; a target edge length and a smoothing displacement bound of 0
   *  are automatic (finishingOptionsFor the grid). */
  SurfaceFinishingOptions finishing{ SurfaceFinish::Remeshed, {}, { 0.0 } };
  /** Threads for the work inside one structure (its connected pieces, the self-intersection check);
   *  0: every core. The mesh does not depend on it. */
  unsigned int threads = 0;
  /** For drawn contours (a structure set's; --holdContours): the finished surface passes through
   *  them. They are resampled keeping their corners (ContourPreparationOptions::keepCorners) and the
   *  finishing leaves their edges as tiled (SurfaceFinishingOptions::heldContours). Not for contours
   *  traced from a mask, a staircase whose corners are not the anatomy's. */
  bool holdContours = false;
};

/** The contour point spacing of a remeshed surface, in target edge lengths, when none is given and
 *  the slices are at least resampledSliceRatio times as thick as the pixels. */
constexpr double remeshedContourSpacing = 1.2;
constexpr double resampledSliceRatio = 1.2;

/** The simplification tolerance of a remeshed surface's traced contours, in pixels, when none is
 *  given: only the points on the straight line between their neighbours go. */
constexpr double collinearTolerance = 1e-3;

/** The longest edge a remeshed surface's simplified contours keep, in target edges. The remesh
 *  halves a longer edge of the tiling until it is short enough, and halving a needle (a wall row
 *  along a straight run of a thousand pixels) makes needles again: a one-voxel bar 8000 voxels long
 *  took 11.6 s and 895 MB, four times as long for twice the length. Eight target edges need three
 *  halvings and, on the benchmark's phantoms and the AAL atlas, cost nothing measurable. */
constexpr double simplifiedEdgeBound = 8.0;

/** The options with every automatic value replaced by its value for a grid of this spacing (x, y,
 *  slice; mm): the contour preparation (resolvedContourPreparation), the finishing
 *  (finishingOptionsFor: the target edge length, the smoothing's displacement bound) and, for a
 *  remeshed surface between slices resampledSliceRatio pixels thick or more, a contour point spacing
 *  of remeshedContourSpacing target edges where none is given (the traced contours' points are kept
 *  otherwise), and for a remeshed surface's traced contours kept at their points a simplification
 *  tolerance of collinearTolerance pixels where none is given, and no simplified edge longer than
 *  simplifiedEdgeBound target edges. */
MeshingOptions resolvedMeshingOptions(const MeshingOptions& options, const std::array<double, 3>& spacing);

} // namespace slicemesh

#endif

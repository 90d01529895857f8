// The smallest lengths a run may ask of the meshing, against the grid it meshes.
#ifndef LengthLimits_h
#define LengthLimits_h

#include "Meshing/MeshingOptions.h"

namespace slicemesh::cli
{

/** A length asked for (--targetEdgeLength, --maxEdgeLength, --wallRowHeight, --contourPointSpacing)
 *  may not be under this share of the smallest voxel side (of an ROI: of its point or slice
 *  spacing). The voxels hold no detail finer than a fraction of their side, and the triangles and
 *  points grow as 1 / length^2 and 1 / length: at 1e-300 mm the run grew without bound, at 0.005 mm
 *  on a 1 mm grid it took gigabytes. A twentieth still allows far finer meshes than anyone needs. */
constexpr double smallestLengthPerVoxelSide = 1.0 / 20.0;

/** Throws PipelineFailure(BadArguments), one line naming the option and the smallest value it
 *  may take, when a length set in `options` (0, automatic, is always allowed) is under
 *  smallestLengthPerVoxelSide * smallestVoxelSide. */
void requireResolvableLengths(const MeshingOptions& options, double smallestVoxelSide);

} // namespace slicemesh::cli

#endif

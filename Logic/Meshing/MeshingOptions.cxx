#include "Meshing/MeshingOptions.h"

namespace slicemesh
{

MeshingOptions resolvedMeshingOptions(const MeshingOptions& options, const std::array<double, 3>& spacing)
{
  MeshingOptions resolved = options;
  resolved.contours = resolvedContourPreparation(options.contours, spacing);
  // The library's finishing for this grid (the automatic edge length, smoothing that moves no vertex
  // farther than a fraction of a voxel), with the given choices on top.
  SurfaceFinishingOptions& finishing = resolved.finishing;
  const SurfaceFinishingOptions automatic = finishingOptionsFor(spacing);
  if (!(finishing.remeshing.targetEdgeLength > 0.0))
    finishing.remeshing.targetEdgeLength = automatic.remeshing.targetEdgeLength;
  if (!(finishing.smoothing.maxDisplacement > 0.0))
    finishing.smoothing.maxDisplacement = automatic.smoothing.maxDisplacement;
  return resolved;
}

} // namespace slicemesh

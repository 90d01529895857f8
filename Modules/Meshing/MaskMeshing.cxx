#include "MaskMeshing.h"

namespace slicemesh
{

MeshedContours startMaskMeshing(const MaskVolume* mask, const MeshingOptions& options, double contourSmoothingSigma)
{
  const auto spacing = mask->GetSpacing();
  return startMeshing(extractContours(mask, contourSmoothingSigma), options, { spacing[0], spacing[1], spacing[2] });
}

MeshedMask meshMask(const MaskVolume* mask, const MeshingOptions& options, double contourSmoothingSigma,
                    CoordinateSystem system, const std::function<void(MeshingStage, double)>& progress)
{
  const auto spacing = mask->GetSpacing();
  MeshedMask result;
  result.meshing = meshContours(extractContours(mask, contourSmoothingSigma), options,
                                { spacing[0], spacing[1], spacing[2] }, progress);
  result.physical = mapToPhysicalSpace(result.meshing.surface.mesh, sliceFrameOf(mask), system);
  return result;
}

} // namespace slicemesh

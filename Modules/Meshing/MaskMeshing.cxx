#include "MaskMeshing.h"

namespace slicemesh
{

double maskVoxelVolume(const MaskVolume* mask)
{
  std::size_t voxels = 0;
  const std::size_t count = mask->GetBufferedRegion().GetNumberOfPixels();
  const auto* value = mask->GetBufferPointer();
  for (std::size_t i = 0; i < count; ++i)
    voxels += value[i] != 0;
  const std::array<double, 3> spacing = meshingSpacing(mask);
  return static_cast<double>(voxels) * spacing[0] * spacing[1] * spacing[2];
}

MeshedContours startMaskMeshing(const MaskVolume* mask, const MeshingOptions& options, double contourSmoothingSigma)
{
  // The finished surface encloses the voxels' volume (their traced contours cut each convex corner).
  return startMeshing(extractContours(mask, contourSmoothingSigma), options, meshingSpacing(mask), maskVoxelVolume(mask));
}

MeshedMask meshMask(const MaskVolume* mask, const MeshingOptions& options, double contourSmoothingSigma,
                    CoordinateSystem system, const std::function<void(MeshingStage, double)>& progress)
{
  MeshedMask result;
  result.meshing = startMaskMeshing(mask, options, contourSmoothingSigma);
  runMeshingStages(result.meshing, progress);
  result.physical = mapToPhysicalSpace(result.meshing.surface.mesh, sliceFrameOf(mask), system);
  return result;
}

} // namespace slicemesh

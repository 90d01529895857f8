// The mask refinement steps in their fixed order.
#include "MaskRefinement.h"

#include "HoleFilling.h"
#include "Core/SliceMeshTypes.h"
#include "SmallRegionRemoval.h"

namespace slicemesh
{
namespace
{

/** Edge voxels that are face neighbours of the mask join it (one step, no chains along the edge). */
void restoreEdgeVoxels(MaskVolume* mask, const MaskVolume* edgeVoxels, ProcessingDimension dimension)
{
  const auto size = mask->GetBufferedRegion().GetSize();
  const long nx = static_cast<long>(size[0]), ny = static_cast<long>(size[1]), nz = static_cast<long>(size[2]);
  const unsigned char* edge = edgeVoxels->GetBufferPointer();
  unsigned char* out = mask->GetBufferPointer();
  const bool in3D = dimension == ProcessingDimension::Volume3D;
  std::vector<long> joining;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
      {
        const long n = (k * ny + j) * nx + i;
        if (!edge[n] || out[n])
          continue;
        const bool touches = (i > 0 && out[n - 1]) || (i + 1 < nx && out[n + 1]) || (j > 0 && out[n - nx]) ||
                             (j + 1 < ny && out[n + nx]) ||
                             (in3D && ((k > 0 && out[n - nx * ny]) || (k + 1 < nz && out[n + nx * ny])));
        if (touches)
          joining.push_back(n);
      }
  for (long n : joining)
    out[n] = 1;
}

} // namespace

void refineMask(MaskVolume* mask, const MaskRefinementOptions& options, const MaskVolume* edgeVoxels)
{
  removeSmallRegions(mask, options.minimumArea, options.dimension);
  keepSeededRegions(mask, options.seeds, options.dimension);
  if (edgeVoxels)
    restoreEdgeVoxels(mask, edgeVoxels, options.dimension);
  if (options.fillHoles)
    fillHoles(mask, options.dimension);

  const unsigned char* voxel = mask->GetBufferPointer();
  const std::size_t count = mask->GetBufferedRegion().GetNumberOfPixels();
  bool empty = true;
  for (std::size_t n = 0; n < count && empty; ++n)
    empty = voxel[n] == 0;
  if (empty)
    throw Error("the mask is empty after removing the regions smaller than the minimum area");
}

} // namespace slicemesh

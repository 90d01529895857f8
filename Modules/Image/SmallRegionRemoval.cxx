// Small-region removal by area: per-slice regions, or 3D components by their largest cross-section.
#include "SmallRegionRemoval.h"

#include <algorithm>
#include <map>

namespace slicemesh
{

std::size_t removeSmallRegions(MaskVolume* mask, double minimumArea, ProcessingDimension dimension)
{
  if (!(minimumArea > 0.0))
    return 0;
  const ComponentLabels components = labelComponents(mask, dimension, 1, false);
  const auto size = mask->GetBufferedRegion().GetSize();
  const std::size_t sliceVoxels = size[0] * size[1];
  const double voxelArea = mask->GetSpacing()[0] * mask->GetSpacing()[1];

  // Largest area of each component in any one slice (in 2D a component lies in one slice).
  std::vector<std::size_t> largest(static_cast<std::size_t>(components.count) + 1, 0);
  std::vector<std::size_t> inSlice(static_cast<std::size_t>(components.count) + 1, 0);
  std::vector<std::int32_t> touched;
  for (std::size_t k = 0; k < size[2]; ++k)
  {
    touched.clear();
    for (std::size_t n = k * sliceVoxels; n < (k + 1) * sliceVoxels; ++n)
    {
      const std::int32_t label = components.labels[n];
      if (label == 0)
        continue;
      if (inSlice[label]++ == 0)
        touched.push_back(label);
    }
    for (std::int32_t label : touched)
    {
      largest[label] = std::max(largest[label], inSlice[label]);
      inSlice[label] = 0;
    }
  }

  unsigned char* out = mask->GetBufferPointer();
  std::size_t removed = 0;
  for (std::size_t n = 0; n < components.labels.size(); ++n)
  {
    const std::int32_t label = components.labels[n];
    if (label != 0 && static_cast<double>(largest[label]) * voxelArea < minimumArea)
    {
      out[n] = 0;
      ++removed;
    }
  }
  return removed;
}

} // namespace slicemesh

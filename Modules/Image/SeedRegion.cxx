// Seeded region selection, per slice with propagation through the stack, or in 3D.
#include "SeedRegion.h"

#include "Core/SliceMeshTypes.h"

#include <sstream>

namespace slicemesh
{
namespace
{

long seedVoxel(const MaskVolume* mask, const PhysicalPoint& seed)
{
  itk::Point<double, 3> point;
  for (int a = 0; a < 3; ++a)
    point[a] = seed[a];
  itk::Index<3> index;
  const bool inside = mask->TransformPhysicalPointToIndex(point, index);
  std::ostringstream where;
  where << "seed point (" << seed[0] << ", " << seed[1] << ", " << seed[2] << ") LPS mm";
  if (!inside)
    throw Error(where.str() + " lies outside the volume");
  const auto region = mask->GetBufferedRegion();
  const auto size = region.GetSize();
  const long i = index[0] - region.GetIndex()[0], j = index[1] - region.GetIndex()[1],
             k = index[2] - region.GetIndex()[2];
  const long n = (k * static_cast<long>(size[1]) + j) * static_cast<long>(size[0]) + i;
  if (mask->GetBufferPointer()[n] == 0)
  {
    std::ostringstream message;
    message << where.str() << " falls on voxel (" << index[0] << ", " << index[1] << ", " << index[2]
            << "), which the segmentation leaves outside; move the seed into the structure or widen the window";
    throw Error(message.str());
  }
  return n;
}

} // namespace

void keepSeededRegions(MaskVolume* mask, const std::vector<PhysicalPoint>& seeds, ProcessingDimension dimension)
{
  if (seeds.empty())
    return;
  std::vector<long> seedVoxels;
  for (const PhysicalPoint& seed : seeds)
    seedVoxels.push_back(seedVoxel(mask, seed));

  const ComponentLabels components = labelComponents(mask, dimension, 1, false);
  std::vector<unsigned char> keep(static_cast<std::size_t>(components.count) + 1, 0);
  for (long n : seedVoxels)
    keep[components.labels[n]] = 1;

  if (dimension == ProcessingDimension::Slice2D)
  {
    // Follow the kept regions from slice to slice, upwards and downwards from every seeded slice.
    const auto size = mask->GetBufferedRegion().GetSize();
    const long sliceVoxels = static_cast<long>(size[0] * size[1]);
    const long nz = static_cast<long>(size[2]);
    for (long n : seedVoxels)
    {
      const long seedSlice = n / sliceVoxels;
      for (int step : { +1, -1 })
      {
        for (long k = seedSlice + step; k >= 0 && k < nz; k += step)
        {
          const long previous = (k - step) * sliceVoxels, current = k * sliceVoxels;
          for (long p = 0; p < sliceVoxels; ++p)
          {
            const std::int32_t below = components.labels[previous + p], here = components.labels[current + p];
            if (below != 0 && keep[below] && here != 0)
            {
              keep[here] = 1;
            }
          }
          // Stop when this slice keeps nothing that the previous one supports.
          bool kept = false;
          for (long p = 0; p < sliceVoxels && !kept; ++p)
          {
            const std::int32_t here = components.labels[current + p];
            kept = here != 0 && keep[here];
          }
          if (!kept)
            break;
        }
      }
    }
  }

  unsigned char* out = mask->GetBufferPointer();
  for (std::size_t n = 0; n < components.labels.size(); ++n)
    if (out[n] && !keep[components.labels[n]])
      out[n] = 0;
}

} // namespace slicemesh

// Connected components of the mask (ITK, 26-connected), sized in voxels, small ones cleared.
#include "SmallComponentRemoval.h"

#include "Core/SliceMeshTypes.h"

#include "itkConnectedComponentImageFilter.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace slicemesh
{

SmallComponentRemoval removeSmallComponents(MaskVolume* mask, double minimumVolume)
{
  if (!mask)
    throw Error("removeSmallComponents: no mask");
  if (!std::isfinite(minimumVolume) || minimumVolume < 0.0)
  {
    std::ostringstream message;
    message << "removeSmallComponents: the minimum component volume is " << minimumVolume
            << " mm^3; it must be finite and >= 0";
    throw Error(message.str());
  }
  SmallComponentRemoval result;
  if (minimumVolume <= 0.0)
    return result;

  using LabelImage = itk::Image<std::uint32_t, 3>;
  using Labeller = itk::ConnectedComponentImageFilter<MaskVolume, LabelImage>;
  auto labeller = Labeller::New();
  labeller->SetInput(mask);
  labeller->FullyConnectedOn(); // 26-connectivity
  try
  {
    labeller->Update();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(std::string("removeSmallComponents: ITK failed: ") + error.GetDescription());
  }
  const LabelImage* labels = labeller->GetOutput();
  const std::size_t count = labeller->GetObjectCount();
  result.components = count;

  const std::size_t voxels = mask->GetBufferedRegion().GetNumberOfPixels();
  const std::uint32_t* label = labels->GetBufferPointer();
  std::vector<std::size_t> size(count + 1, 0);
  for (std::size_t v = 0; v < voxels; ++v)
    ++size[label[v]];

  const auto spacing = mask->GetSpacing();
  const double voxelVolume = spacing[0] * spacing[1] * spacing[2];
  std::vector<unsigned char> drop(count + 1, 0);
  for (std::size_t c = 1; c <= count; ++c)
  {
    const double volume = static_cast<double>(size[c]) * voxelVolume;
    result.largestComponentVolume = std::max(result.largestComponentVolume, volume);
    if (volume < minimumVolume)
    {
      drop[c] = 1;
      ++result.removedComponents;
      result.removedVoxels += size[c];
    }
  }
  if (result.removedComponents == 0)
    return result;
  unsigned char* voxel = mask->GetBufferPointer();
  for (std::size_t v = 0; v < voxels; ++v)
    if (drop[label[v]])
      voxel[v] = 0;
  mask->Modified();
  return result;
}

} // namespace slicemesh

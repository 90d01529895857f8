// Runs a 2D ITK filter on every slice of a volume (the slices along the third index axis).
#ifndef PerSliceFilter_h
#define PerSliceFilter_h

#include "VolumeReader.h"

#include <algorithm>

namespace slicemesh
{

using SliceImage2D = itk::Image<float, 2>;

/** For each slice k: copies it into a 2D image with the volume's in-plane spacing, calls
 *  filterSlice(slice) -> 2D image of the same size, and copies the result into slice k of a new
 *  volume with the input's geometry. The 2D origin is 0 and its direction the identity: the filters
 *  used here depend on spacing only. */
template <typename OutputVolume, typename FilterSlice>
typename OutputVolume::Pointer filterEachSlice(const ScalarVolume* volume, FilterSlice filterSlice)
{
  const auto region = volume->GetBufferedRegion();
  const auto size = region.GetSize();
  auto output = OutputVolume::New();
  output->CopyInformation(volume);
  output->SetRegions(region);
  output->Allocate();

  const std::size_t sliceVoxels = size[0] * size[1];
  for (std::size_t k = 0; k < size[2]; ++k)
  {
    auto slice = SliceImage2D::New();
    SliceImage2D::SizeType sliceSize{ { size[0], size[1] } };
    slice->SetRegions(SliceImage2D::RegionType(sliceSize));
    SliceImage2D::SpacingType spacing;
    spacing[0] = volume->GetSpacing()[0];
    spacing[1] = volume->GetSpacing()[1];
    slice->SetSpacing(spacing);
    slice->Allocate();
    const float* in = volume->GetBufferPointer() + k * sliceVoxels;
    std::copy(in, in + sliceVoxels, slice->GetBufferPointer());
    const auto filtered = filterSlice(slice.GetPointer());
    const auto* result = filtered->GetBufferPointer();
    auto* out = output->GetBufferPointer() + k * sliceVoxels;
    for (std::size_t n = 0; n < sliceVoxels; ++n)
      out[n] = static_cast<typename OutputVolume::PixelType>(result[n]);
  }
  return output;
}

} // namespace slicemesh

#endif

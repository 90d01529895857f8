// Small hand-made images for the image module's tests.
#ifndef TestVolumes_h
#define TestVolumes_h

#include "VolumeReader.h"

#include <array>

namespace slicemesh::testing
{

/** An all-zero image of the given size and spacing, origin 0, identity direction. */
template <typename TImage>
typename TImage::Pointer makeImage(std::array<std::size_t, 3> size, std::array<double, 3> spacing = { 1.0, 1.0, 1.0 })
{
  auto image = TImage::New();
  typename TImage::SizeType itkSize;
  typename TImage::SpacingType itkSpacing;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    itkSize[axis] = size[axis];
    itkSpacing[axis] = spacing[axis];
  }
  image->SetRegions(itkSize);
  image->SetSpacing(itkSpacing);
  image->Allocate(true);
  return image;
}

inline MaskVolume::Pointer makeMask(std::array<std::size_t, 3> size, std::array<double, 3> spacing = { 1.0, 1.0, 1.0 })
{
  return makeImage<MaskVolume>(size, spacing);
}

inline ScalarVolume::Pointer makeVolume(std::array<std::size_t, 3> size, std::array<double, 3> spacing = { 1.0, 1.0, 1.0 })
{
  return makeImage<ScalarVolume>(size, spacing);
}

template <typename TImage>
void setVoxel(TImage* image, long i, long j, long k, typename TImage::PixelType value)
{
  image->SetPixel({ { i, j, k } }, value);
}

} // namespace slicemesh::testing

#endif

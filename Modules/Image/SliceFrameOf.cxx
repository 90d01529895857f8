// The stack frame of an image: where Logic's millimetre coordinates sit in physical space.
#include "ContourExtraction.h"

#include <cmath>

namespace slicemesh
{

std::array<double, 3> meshingSpacing(const itk::ImageBase<3>* image)
{
  constexpr int digits = 6;
  std::array<double, 3> spacing{};
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const double s = image->GetSpacing()[axis];
    if (!(s > 0.0) || !std::isfinite(s))
    {
      spacing[axis] = s;
      continue;
    }
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(s)));
    spacing[axis] = std::round(s * scale) / scale;
  }
  return spacing;
}

SliceFrame sliceFrameOf(const itk::ImageBase<3>* image)
{
  SliceFrame frame;
  const std::array<double, 3> spacing = meshingSpacing(image);
  // The stack frame counts voxels from the start of the image's region (index 0 for any image
  // read from a file), so its origin is the physical centre of that first voxel.
  const auto start = image->GetLargestPossibleRegion().GetIndex();
  itk::Point<double, 3> firstVoxel;
  image->TransformIndexToPhysicalPoint(start, firstVoxel);
  for (unsigned int row = 0; row < 3; ++row)
  {
    frame.origin[row] = firstVoxel[row];
    frame.spacing[row] = spacing[row];
    for (unsigned int column = 0; column < 3; ++column)
      frame.direction[row][column] = image->GetDirection()[row][column];
  }
  return frame;
}

} // namespace slicemesh

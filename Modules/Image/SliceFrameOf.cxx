// The stack frame of an image: where Logic's millimetre coordinates sit in physical space.
#include "ContourExtraction.h"

namespace slicemesh
{

SliceFrame sliceFrameOf(const itk::ImageBase<3>* image)
{
  SliceFrame frame;
  // The stack frame counts voxels from the start of the image's region (index 0 for any image
  // read from a file), so its origin is the physical centre of that first voxel.
  const auto start = image->GetLargestPossibleRegion().GetIndex();
  itk::Point<double, 3> firstVoxel;
  image->TransformIndexToPhysicalPoint(start, firstVoxel);
  for (unsigned int row = 0; row < 3; ++row)
  {
    frame.origin[row] = firstVoxel[row];
    frame.spacing[row] = image->GetSpacing()[row];
    for (unsigned int column = 0; column < 3; ++column)
      frame.direction[row][column] = image->GetDirection()[row][column];
  }
  return frame;
}

} // namespace slicemesh

// Per-slice sub-voxel contours of a binary mask, in the stack frame (mm).
#ifndef ContourExtraction_h
#define ContourExtraction_h

#include "Core/SliceMeshTypes.h"
#include "VolumeReader.h"

namespace slicemesh
{

/** The stack frame of an image: its origin, spacing and direction matrix. */
SliceFrame sliceFrameOf(const itk::ImageBase<3>* image);

/** Closed contours at the 0.5 level of the mask in every slice along the third index axis.
 *  Slice k has z = k * spacing[2]; points are (i * spacing[0], j * spacing[1]) in continuous index
 *  i, j. The stack holds every slice of the image, empty ones included.
 *  inPlaneSigma > 0 (mm) smooths each slice with an in-plane Gaussian of that standard deviation
 *  first (SliceSmoothing.h) and traces the smoothed field at 0.5: contours without the voxel
 *  staircase. Slices are smoothed independently, never across slices. */
ContourStack extractContours(const MaskVolume* mask, double inPlaneSigma = 0.0);

} // namespace slicemesh

#endif

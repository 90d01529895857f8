// Per-slice sub-voxel contours of a binary mask, in the stack frame (mm).
#ifndef ContourExtraction_h
#define ContourExtraction_h

#include "Core/SliceMeshTypes.h"
#include "VolumeReader.h"

namespace slicemesh
{

/** The spacing an image is meshed at (mm): its own, each axis rounded to six significant digits.
 *  One tool writes a header in double precision, another in single (NIfTI), or a direction matrix
 *  rounded to single precision changes the spacing's columns' lengths, by parts in 10^8: the
 *  remesh's choices are not continuous in the coordinates, and such a change gave a label a few
 *  triangles more or less and moved its centroid by up to 0.1 mm. Rounded, the same voxels give the
 *  same mesh; the voxels move by under a part in a million of their distance from the origin. */
std::array<double, 3> meshingSpacing(const itk::ImageBase<3>* image);

/** The stack frame of an image: its origin, meshingSpacing and direction matrix. */
SliceFrame sliceFrameOf(const itk::ImageBase<3>* image);

/** Closed contours at the 0.5 level of the mask in every slice along the third index axis.
 *  Slice k has z = k * spacing[2]; points are (i * spacing[0], j * spacing[1]) in continuous index
 *  i, j, spacing the mask's meshingSpacing. The stack holds every slice of the image, empty ones included.
 *  inPlaneSigma > 0 (mm) smooths each slice with an in-plane Gaussian of that standard deviation
 *  first (SliceSmoothing.h) and traces the smoothed field at 0.5: contours without the voxel
 *  staircase. Slices are smoothed independently, never across slices. */
ContourStack extractContours(const MaskVolume* mask, double inPlaneSigma = 0.0);

} // namespace slicemesh

#endif

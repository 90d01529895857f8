// Canny edges of a grayscale volume, per slice or in 3D, as a mask.
#ifndef CannyEdges_h
#define CannyEdges_h

#include "ComponentLabeling.h"

namespace slicemesh
{

struct CannyOptions
{
  /** Variance of the Gaussian that smooths before the gradient, in mm^2. */
  double variance = 2.0;
  /** Hysteresis thresholds on the gradient magnitude (intensity units per voxel step): a chain of
   *  edge voxels is kept when one of its voxels is above the upper threshold and all are above
   *  the lower one. */
  double lowerThreshold = 5.0;
  double upperThreshold = 15.0;
};

/** 1 on the edge voxels that ITK's CannyEdgeDetectionImageFilter finds, 0 elsewhere. Per slice
 *  (2D, the paper's per-slice edge detector) or in 3D. */
MaskVolume::Pointer cannyEdges(const ScalarVolume* volume, const CannyOptions& options, ProcessingDimension dimension);

} // namespace slicemesh

#endif

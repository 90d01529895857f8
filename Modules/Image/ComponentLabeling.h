// Connected components of a binary mask, per slice (2D) or in the whole volume (3D).
#ifndef ComponentLabeling_h
#define ComponentLabeling_h

#include "VolumeReader.h"

#include <cstdint>
#include <vector>

namespace slicemesh
{

/** Whether a mask operation looks at one slice at a time (the slices along the third index axis,
 *  as the contour method does) or at the whole volume. */
enum class ProcessingDimension
{
  Slice2D, ///< per slice (default, as the paper): in-plane neighbours only
  Volume3D ///< the whole volume
};

/** Component labels of the voxels whose mask value equals `value` (1 for the foreground, 0 for the
 *  background). Neighbours: in 2D, 4-connected (faces) or, with `wide`, 8-connected (faces and
 *  corners) within each slice; in 3D, 6-connected or, with `wide`, 26-connected. The foreground
 *  uses the narrow neighbourhood (the contours separate voxels touching only at a corner), the
 *  background the wide one (its dual, so a hole is closed exactly when its ring is).
 *  Returns one label per voxel (0 for voxels of the other value, else 1..count), in raster order,
 *  so the labels are deterministic. */
struct ComponentLabels
{
  std::vector<std::int32_t> labels;
  std::int32_t count = 0;
};
ComponentLabels labelComponents(const MaskVolume* mask, ProcessingDimension dimension, unsigned char value,
                                bool wide);

} // namespace slicemesh

#endif

// Drops connected components of a mask that are smaller than a volume in mm^3 (specks, noise).
#ifndef SmallComponentRemoval_h
#define SmallComponentRemoval_h

#include "VolumeReader.h"

#include <cstddef>

namespace slicemesh
{

struct SmallComponentRemoval
{
  std::size_t components = 0;        ///< connected components of the mask before removal
  std::size_t removedComponents = 0; ///< those smaller than the minimum volume
  std::size_t removedVoxels = 0;
  double largestComponentVolume = 0.0; ///< mm^3, of every component before removal
};

/** Clears, in place, every connected component of the mask (non-zero voxels) whose volume
 *  (voxel count times the voxel volume, mm^3) is smaller than minimumVolume.
 *
 *  Components are 26-connected (voxels touching at a face, an edge or a corner are one component):
 *  only what is isolated under any connectivity is dropped, so a chain of voxels touching at edges
 *  is judged as a whole. minimumVolume <= 0 keeps everything and returns at once.
 *  The mask may end up empty; the caller decides what that means. Throws slicemesh::Error on a
 *  negative or non-finite minimum volume. Uses 4 bytes per voxel of extra memory while it runs. */
SmallComponentRemoval removeSmallComponents(MaskVolume* mask, double minimumVolume);

} // namespace slicemesh

#endif

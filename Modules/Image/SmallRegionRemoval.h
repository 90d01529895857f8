// Removes the pieces of a binary mask whose area in a slice is below a limit (mm^2).
#ifndef SmallRegionRemoval_h
#define SmallRegionRemoval_h

#include "ComponentLabeling.h"

namespace slicemesh
{

/** 2D: removes every 4-connected region of a slice whose area (voxels times the in-plane spacing
 *  product) is below minimumArea mm^2. 3D: removes every 6-connected component whose largest
 *  cross-section in any slice is below minimumArea mm^2 (so the same speck is removed in either
 *  mode, and a thin structure that is large in some slice is kept whole). Returns the number of
 *  voxels removed; minimumArea <= 0 removes nothing. */
std::size_t removeSmallRegions(MaskVolume* mask, double minimumArea, ProcessingDimension dimension);

} // namespace slicemesh

#endif

// Keeps only the connected regions of a binary mask that contain seed points.
#ifndef SeedRegion_h
#define SeedRegion_h

#include "ComponentLabeling.h"

#include <array>
#include <vector>

namespace slicemesh
{

/** A point in physical LPS millimetres (ITK's physical space; SliceMesh.xml declares its `seed`
 *  point parameter with coordinateSystem="lps", so 3D Slicer converts its RAS markups to LPS). */
using PhysicalPoint = std::array<double, 3>;

/** Keeps the regions of the mask that contain a seed, removes the rest.
 *  3D: the 6-connected components that hold a seed voxel.
 *  2D (per slice): in the seed's own slice, the 4-connected region holding the seed; then slice by
 *  slice away from it (both ways), the 4-connected regions of the next slice that overlap (share an
 *  in-plane voxel with) what was kept in the previous one, until a slice keeps nothing: the region
 *  is followed through the stack as the contour method sees it.
 *  Each seed is rounded to its nearest voxel. Throws slicemesh::Error when a seed lies outside the
 *  volume or on a background voxel (the message gives the point and the voxel). */
void keepSeededRegions(MaskVolume* mask, const std::vector<PhysicalPoint>& seeds, ProcessingDimension dimension);

} // namespace slicemesh

#endif

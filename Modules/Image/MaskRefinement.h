// What is done to a binary mask before its contours are traced: small regions, seeds, holes.
#ifndef MaskRefinement_h
#define MaskRefinement_h

#include "SeedRegion.h"

namespace slicemesh
{

struct MaskRefinementOptions
{
  ProcessingDimension dimension = ProcessingDimension::Slice2D;
  /** Keep only the regions holding these points (physical LPS mm); empty keeps all. */
  std::vector<PhysicalPoint> seeds;
  bool fillHoles = false;
  /** Remove regions whose area in a slice is below this (mm^2); 0 keeps all. */
  double minimumArea = 0.0;

  bool any() const { return !seeds.empty() || fillHoles || minimumArea > 0.0; }
};

/** In this order: removeSmallRegions, keepSeededRegions, give back the cut edge voxels (edge mode)
 *  that touch a kept voxel (in-plane face neighbours in 2D, face neighbours in 3D), fillHoles.
 *  Throws slicemesh::Error (from the seeds, or when nothing is left). */
void refineMask(MaskVolume* mask, const MaskRefinementOptions& options, const MaskVolume* edgeVoxels = nullptr);

} // namespace slicemesh

#endif

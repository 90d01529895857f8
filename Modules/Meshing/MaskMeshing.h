// A mask meshed through the one meshing path: its contours traced, meshContours (Logic), the surface
// mapped to physical space.
#ifndef MaskMeshing_h
#define MaskMeshing_h

#include "ContourExtraction.h"
#include "MeshWriter.h"
#include "Meshing/MeshContours.h"

namespace slicemesh
{

/** The volume of the mask's voxels (its non-zero voxels times the voxel volume; mm^3). */
double maskVoxelVolume(const MaskVolume* mask);

/** The mask's contours traced at its 0.5 level (after an in-plane Gaussian of `contourSmoothingSigma`
 *  mm, if above 0), at the start of the meshing path with the options resolved for its spacing and
 *  the volume of its voxels as the finished surface's volume. */
MeshedContours startMaskMeshing(const MaskVolume* mask, const MeshingOptions& options,
                                double contourSmoothingSigma = 0.0);

struct MeshedMask
{
  MeshedContours meshing; ///< in the stack frame
  TriangleMesh physical;  ///< the finished surface in physical millimetres of `system`
};

/** startMaskMeshing, every stage of the path, then the surface in physical space. */
MeshedMask meshMask(const MaskVolume* mask, const MeshingOptions& options = {}, double contourSmoothingSigma = 0.0,
                    CoordinateSystem system = CoordinateSystem::LPS,
                    const std::function<void(MeshingStage, double)>& progress = {});

} // namespace slicemesh

#endif

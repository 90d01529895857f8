// 3D Slicer's default label map -> closed surface conversion, reproduced with VTK, for the
// benchmarks: the peer SliceMesh is measured against (vtkBinaryLabelmapToClosedSurfaceConversionRule
// of Slicer 5.x at smoothing factor 0.5, decimation off).
#ifndef SlicerPipeline_h
#define SlicerPipeline_h

#include "Core/SliceMeshTypes.h"
#include "VolumeReader.h"

namespace slicemesh
{

/** The surface of the mask's non-zero voxels as Slicer makes it, in the stack frame (index times
 *  spacing, mm): pad by one voxel, vtkDiscreteFlyingEdges3D in index space,
 *  vtkWindowedSincPolyDataFilter (pass band 10^(-4 s), 20 + 40 s iterations, boundary and
 *  feature-edge smoothing off, non-manifold smoothing on, normalized coordinates) and
 *  vtkPolyDataNormals (consistency on, splitting off; computed as Slicer does, not returned). */
TriangleMesh slicerSurface(const MaskVolume* mask, double smoothing = 0.5);

} // namespace slicemesh

#endif

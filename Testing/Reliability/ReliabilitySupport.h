// The real path from a mask to a checked mesh, and seeded random label maps, for the reliability
// tests (hard geometry, the property test) and the fuzz targets.
#ifndef ReliabilitySupport_h
#define ReliabilitySupport_h

#include "MaskMeshing.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"
#include "VolumeReader.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>

namespace slicemesh::testing
{

/** A mask of the given size, spacing, origin 0 and direction (columns: axis unit vectors). */
MaskVolume::Pointer makeMask(std::array<std::size_t, 3> size, std::array<double, 3> spacing = { 1.0, 1.0, 1.0 },
                             const std::array<std::array<double, 3>, 3>& direction = { { { 1.0, 0.0, 0.0 },
                                                                                        { 0.0, 1.0, 0.0 },
                                                                                        { 0.0, 0.0, 1.0 } } });

/** A mask whose voxel (i, j, k) is inside(i, j, k). */
MaskVolume::Pointer makeMask(std::array<std::size_t, 3> size, std::array<double, 3> spacing,
                             const std::function<bool(long, long, long)>& inside);

struct MaskMeshResult
{
  std::string error;         ///< what the meshing path threw, else empty
  MeshedContours meshing;    ///< the path's stages (stack frame): tiling, its validation, finished surface
  TriangleMesh mesh;         ///< the surface written: physical (LPS) millimetres
  MeshValidation validation; ///< of the physical mesh
  double voxelVolume = 0.0;  ///< number of mask voxels times the voxel volume (mm^3)
  double voxelFaceArea = 0.0; ///< area of the boundary faces of the voxels (mm^2)
  double maxSpacing = 0.0;
  std::size_t contours = 0;

  /** The stated volume tolerance: the mesh lies within half a voxel of the voxels' boundary (0.5
   *  level contours, caps half a slice beyond), so its volume differs from the voxels' by less than
   *  a shell a quarter of the largest spacing thick over the voxels' boundary faces. */
  double volumeTolerance() const { return (capsAtSlice ? 0.5 : 0.25) * maxSpacing * voxelFaceArea; }
  /** Meshed with CapPlacement::AtSlice: the end caps lie on the last contours, up to half a voxel
   *  inside the voxels, so the shell of the tolerance is half a spacing thick. */
  bool capsAtSlice = false;
  bool volumeWithinTolerance() const
  {
    return std::abs(validation.volume - voxelVolume) <= volumeTolerance();
  }
  /** valid() and the volume check, with a one-line reason when not. */
  std::string problem() const;
};

/** The mask through the one meshing path (startMaskMeshing, every stage), mapped to physical space
 *  (LPS) and validated there. */
MaskMeshResult checkedMesh(const MaskVolume* mask, const MeshingOptions& options);

/** The tiling alone (the traced contours, these tiling options, finish Tiled): what the property
 *  tests check. */
MaskMeshResult checkedMesh(const MaskVolume* mask, const ReconstructionOptions& options = {});

/** Kinds of random label maps the property test draws from. */
enum class RandomMaskKind
{
  Blobs,        ///< a few random ellipsoids, some cut by the image border
  Noise,        ///< independent voxels (salt), thin to dense
  BlobsAndNoise,
  Touching,     ///< voxels placed to touch only at edges and corners (diagonal runs, checkerboards)
  Thin,         ///< one-slice-thick sheets and one-voxel rods
  /** A smooth random field thresholded, as a grayscale MRI is: many thin, touching and holed
   *  pieces, cut off flat at a random first and last slice, capped flat (AtSlice) half the time. */
  ThresholdedMri,
  Any           ///< one of Blobs .. Thin, by the seed
};

struct RandomMask
{
  MaskVolume::Pointer mask;
  std::string description; ///< size, spacing, direction, kind and caps, to reproduce by hand
  ReconstructionOptions options; ///< the cap placement drawn for the mask (the default otherwise)
};

/** A random mask, the same for the same seed and kind: size 1..16 per axis (12..28 for
 *  ThresholdedMri), isotropic, anisotropic or thick-slice spacing, identity, oblique, mirrored or
 *  permuted direction. */
RandomMask randomMask(std::uint64_t seed, RandomMaskKind kind);

/** The mask as C++ source (a makeMask call with the set voxels listed): a reproducer to paste. */
std::string maskAsCode(const MaskVolume* mask);

} // namespace slicemesh::testing

#endif

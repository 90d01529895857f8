// Shared helpers of the real-data tests: where the data is, meshing a mask, boxes.
#ifndef RealDataSupport_h
#define RealDataSupport_h

#include "Measures/MeshValidation.h"
#include "MeshWriter.h"
#include "Tiling/SurfaceReconstruction.h"
#include "VolumeReader.h"

#include <array>
#include <string>
#include <vector>

namespace slicemesh::testing
{

/** The Debian packages' files the tests read. */
inline const std::string mricronTemplates = "/usr/share/mricron/templates/";
inline const std::string itkExamplesData = "/usr/share/doc/insighttoolkit5-examples/examples/Data/";
std::string externalData(const std::string& name);
std::string outputPath(const std::string& name);

struct Box
{
  std::array<double, 3> lower{ 1e300, 1e300, 1e300 };
  std::array<double, 3> upper{ -1e300, -1e300, -1e300 };
  void add(const std::array<double, 3>& p);
  bool contains(const Box& inner, double tolerance) const;
};

struct MaskMesh
{
  TriangleMesh physical; ///< LPS mm
  MeshValidation validation;
  Box meshBox;
  Box centreBox; ///< physical box of the mask's voxel centres
  Box cubeBox;   ///< physical box of the mask's voxel cubes (centres +- half a voxel on each axis)
  double voxelVolume = 0.0;
};

/** The tiling by the one meshing path (meshMask, finish Tiled), its validation, physical space, and
 *  the boxes to compare. */
MaskMesh tiledMask(const MaskVolume* mask, const ReconstructionOptions& options = {});

/** Which background voxels a cavity count takes as neighbours. */
enum class BackgroundConnectivity
{
  Faces6,    ///< voxels sharing a face
  Corners26, ///< sharing a face, an edge or a corner
  /** What the contour method leaves open between voxel centres (measured: see
   *  AtlasLabels.CavityRuleAgreesWithTheMeshAroundEveryEdgeAcrossTheSlices). Always: the 8
   *  neighbours in the slice (the contours are 4-connected, so the background passes where two
   *  foreground voxels touch at a corner) and the 2 across the slices. Never directly: corner
   *  neighbours across the slices. Across the slices at an edge (dk = +-1 and one of di, dj = +-1),
   *  when both voxels of the edge's other diagonal are foreground and their regions in the two
   *  slices (4-connected) are tiled together (linked by regions overlapping from one slice to the
   *  next): only where, in a square of voxel centres beside the edge, the two slices' contour
   *  segments through the edge's middle coincide (the background pieces share a stretch of
   *  boundary), or both slices have a saddle (a 2 x 2 x 2 checkerboard). Otherwise, always. */
  SliceContours
};

/** Enclosed cavities of a mask: connected pieces of its background (a 3D flood fill with the
 *  given neighbours) that do not reach the border of the mask's region, i.e. are closed off from
 *  the outside by the foreground. */
std::size_t enclosedCavities(const MaskVolume* mask, BackgroundConnectivity connectivity);

/** The signed volume (mm^3) of each connected piece of a mesh (pieces joined at shared vertices),
 *  in the order of each piece's first vertex: positive for an outward-oriented outer surface,
 *  negative for the inner surface of a cavity. */
std::vector<double> componentVolumes(const TriangleMesh& mesh);

} // namespace slicemesh::testing

#endif

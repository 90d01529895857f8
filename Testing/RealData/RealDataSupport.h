// Shared helpers of the real-data tests: where the data is, meshing a mask, boxes.
#ifndef RealDataSupport_h
#define RealDataSupport_h

#include "MeshValidation.h"
#include "MeshWriter.h"
#include "SurfaceReconstruction.h"
#include "VolumeReader.h"

#include <array>
#include <string>

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

/** Contours -> reconstruction -> validation -> physical space, and the boxes to compare. */
MaskMesh meshMask(const MaskVolume* mask, const ReconstructionOptions& options = {});

} // namespace slicemesh::testing

#endif

// Maps a stack-frame mesh to physical space and writes it with VTK.
#ifndef MeshWriter_h
#define MeshWriter_h

#include "SliceMeshTypes.h"

#include <string>

namespace slicemesh
{

enum class CoordinateSystem
{
  LPS, ///< ITK / DICOM physical space, what 3D Slicer assumes for model files (default)
  RAS  ///< 3D Slicer's scene space
};

/** Stack frame -> physical space: p = origin + direction * (x, y, z), then to RAS if asked.
 *  Flips the winding when the mapping mirrors (negative determinant) so normals still point out. */
TriangleMesh mapToPhysicalSpace(const TriangleMesh& stackMesh, const SliceFrame& frame, CoordinateSystem system);

/** Writes .vtp, .vtk, .stl, .ply or .obj by the file's extension, tagged with its coordinate system
 *  (SPACE field data / header) as 3D Slicer reads it. Writes to a temporary name in the target
 *  folder and renames on success; on failure the existing file is untouched. Throws slicemesh::Error. */
void writeMesh(const TriangleMesh& physicalMesh, CoordinateSystem system, const std::string& path);

} // namespace slicemesh

#endif

// Maps a stack-frame mesh to physical space and writes it with VTK.
#ifndef MeshWriter_h
#define MeshWriter_h

#include "Core/SliceMeshTypes.h"
#include "FileReplacement.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

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

/** What a mesh of labelled structures carries besides its geometry. */
struct MeshAttributes
{
  /** Per triangle (empty, or one per triangle): the label value, written as the integer cell
   *  array "Label" (.vtp, .vtk, .ply). */
  std::vector<int> cellLabels;
  /** Per triangle (empty, or one per triangle): RGB, written as the unsigned char cell array
   *  "Color" (.vtp, .vtk) and as the face colours of .ply (red, green, blue). */
  std::vector<std::array<unsigned char, 3>> cellColors;
  /** The structures in the mesh: written as field data "LabelValue" (int), "LabelName" (string)
   *  and "LabelColor" (RGBA, 0..1 floats) in .vtp and .vtk. */
  struct Structure
  {
    int value = 0;
    std::string name;
    std::array<unsigned char, 4> rgba{ 128, 128, 128, 255 };
  };
  std::vector<Structure> structures;
};

/** writeMesh with attributes; .stl and .obj have no place for them and get the geometry only. */
void writeMesh(const TriangleMesh& physicalMesh, CoordinateSystem system, const std::string& path,
               const MeshAttributes& attributes);

/** writeMesh's file written whole to its temporary but not moved into place: the caller commits
 *  it, alone or with others that must replace their files together (commitTogether); dropped
 *  uncommitted, it leaves the place as it was. Throws slicemesh::Error as writeMesh does. */
std::unique_ptr<FileReplacement> writeMeshUncommitted(const TriangleMesh& physicalMesh, CoordinateSystem system,
                                                      const std::string& path, const MeshAttributes& attributes);

} // namespace slicemesh

#endif

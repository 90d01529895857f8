// Reads a mesh file back: what writeMesh wrote, with its labelled structures.
#ifndef MeshReader_h
#define MeshReader_h

#include "MeshWriter.h"

#include <string>

namespace slicemesh
{

struct MeshFile
{
  TriangleMesh mesh;          ///< the file's points (as written: physical millimetres) and triangles
  MeshAttributes attributes;  ///< the "Label" and "Color" cell arrays and the structures, where present
};

/** Reads a .vtp or .vtk polydata file (triangles; other cells are skipped). Throws slicemesh::Error
 *  when the file cannot be read. */
MeshFile readMesh(const std::string& path);

} // namespace slicemesh

#endif

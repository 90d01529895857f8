// The snapshot (MeshSnapshot.h) is rendered by the plugin SliceMeshSnapshotRendering (Modules/Plugins):
// only a run that draws a picture loads VTK's rendering, OpenGL and X.
#ifndef SnapshotPlugin_h
#define SnapshotPlugin_h

#include "MeshSnapshot.h"

#include <cstddef>

namespace slicemesh
{

/** What the plugin does, as its table of functions: snapshotAvailable and the two writeSnapshot. */
struct SnapshotFunctions
{
  std::size_t size; ///< sizeof(SnapshotFunctions) as the plugin was built (pluginFunctions)
  bool (*available)(std::string* reason);
  void (*writeQuality)(const TriangleMesh& physicalMesh, const std::string& path, const SnapshotOptions& options);
  void (*writeStructures)(const TriangleMesh& meshes, const std::vector<std::array<unsigned char, 3>>& triangleColors,
                          const std::string& path, const SnapshotOptions& options);
};

/** The plugin's functions, the plugin loaded on first use. Throws slicemesh::Error when it cannot
 *  be loaded. */
const SnapshotFunctions& snapshotFunctions();

} // namespace slicemesh

#endif

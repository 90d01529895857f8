#include "MeshSnapshot.h"

#include "PluginLoader.h"
#include "SnapshotPlugin.h"

namespace slicemesh
{

const SnapshotFunctions& snapshotFunctions()
{
  return pluginFunctions<SnapshotFunctions>("libSliceMeshSnapshotRendering.so", "slicemeshSnapshotFunctions",
                                            "A snapshot");
}

bool snapshotAvailable(std::string* reason)
{
  const SnapshotFunctions* functions = nullptr;
  try
  {
    functions = &snapshotFunctions();
  }
  catch (const Error& error)
  {
    if (reason)
      *reason = error.what();
    return false;
  }
  return functions->available(reason);
}

void writeSnapshot(const TriangleMesh& physicalMesh, const std::string& path, const SnapshotOptions& options)
{
  snapshotFunctions().writeQuality(physicalMesh, path, options);
}

void writeSnapshot(const TriangleMesh& meshes, const std::vector<std::array<unsigned char, 3>>& triangleColors,
                   const std::string& path, const SnapshotOptions& options)
{
  snapshotFunctions().writeStructures(meshes, triangleColors, path, options);
}

} // namespace slicemesh

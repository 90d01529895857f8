// The parts of SliceMesh that need large libraries only some runs use - GDCM and DCMTK for DICOM,
// VTK's OpenGL rendering for the snapshot - are plugins: shared libraries loaded the first time a
// run needs one. Linked into the executable, those libraries cost every run their loading and
// start-up (GDCM builds its DICOM dictionary in memory): together about 0.06 s and 22 MB of a
// run that reads a NRRD file and draws no picture.
#ifndef PluginLoader_h
#define PluginLoader_h

#include "Core/SliceMeshTypes.h"

#include <cstddef>
#include <string>

namespace slicemesh
{

/** The folder, beside the SliceMesh executable, that holds its plugins. */
constexpr const char* pluginFolderName = "SliceMeshPlugins";

/** The address of the C function `entry` of the plugin library `library` (a file name, e.g.
 *  "libSliceMeshImageDicom.so"), loading the library on first use. Looked for, in order: already in
 *  the process (a program that linked or loaded it itself), in pluginFolderName beside the running
 *  executable (the build tree and an installed SliceMesh alike), else, for a program without such a
 *  folder (a test program), in the build tree's plugin folder. Throws slicemesh::Error saying what
 *  `purpose` needs and why the library could not be loaded. */
void* pluginEntry(const std::string& library, const char* entry, const std::string& purpose);

/** The plugin's table of functions: `entry` is a C function taking nothing and returning a pointer
 *  to a `Functions` struct that lives as long as the process. Its first member, `size`, is the
 *  struct's size as the plugin was built: a plugin whose table has other functions than this build's
 *  (a plugin of another SliceMesh version) is refused with slicemesh::Error, not called. */
template <typename Functions>
const Functions& pluginFunctions(const std::string& library, const char* entry, const std::string& purpose)
{
  using Getter = const Functions* (*)();
  const Functions& functions = *reinterpret_cast<Getter>(pluginEntry(library, entry, purpose))();
  if (functions.size != sizeof(Functions))
    throw Error(purpose + " needs SliceMesh's plugin " + library + ", and the one found is of another SliceMesh version");
  return functions;
}

} // namespace slicemesh

#endif

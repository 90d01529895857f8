#include "PluginLoader.h"

#include "Core/SliceMeshTypes.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <system_error>
#include <vector>

namespace slicemesh
{
namespace
{

/** The folder of the running executable, empty if the system does not say. */
std::filesystem::path executableFolder()
{
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : executable.parent_path();
}

/** The places to load `library` from, in order (see pluginEntry). The build tree's folder only for
 *  a program without a plugin folder of its own (a test program): an installed SliceMesh whose
 *  folder lacks a plugin must say so, not load a build tree's, perhaps of another version. */
std::vector<std::string> candidates(const std::string& library)
{
  std::vector<std::string> places;
  const std::filesystem::path folder = executableFolder();
  std::error_code error;
  const bool ownFolder = !folder.empty() && std::filesystem::is_directory(folder / pluginFolderName, error);
  if (ownFolder)
    places.push_back((folder / pluginFolderName / library).string());
#ifdef SLICEMESH_PLUGIN_BUILD_DIR
  else
    places.push_back((std::filesystem::path(SLICEMESH_PLUGIN_BUILD_DIR) / library).string());
#endif
  return places;
}

/** The handle of `library`, loaded if it is not in the process yet; null with `why` set if it
 *  cannot be. Plugins stay loaded until the process ends. */
void* handleOf(const std::string& library, std::string& why)
{
  if (void* loaded = dlopen(library.c_str(), RTLD_NOW | RTLD_NOLOAD))
    return loaded;
  for (const std::string& place : candidates(library))
  {
    std::error_code error;
    if (!std::filesystem::exists(place, error))
      continue;
    if (void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL))
      return handle;
    const char* message = dlerror();
    why = message ? message : "it cannot be loaded";
    return nullptr;
  }
  why = "it is not in the folder " + std::string(pluginFolderName) + " beside the SliceMesh executable";
  return nullptr;
}

} // namespace

void* pluginEntry(const std::string& library, const char* entry, const std::string& purpose)
{
  // One plugin loaded at a time: a plugin's first load (its libraries' start-up) is done once.
  static std::mutex loading;
  const std::lock_guard<std::mutex> lock(loading);
  std::string why;
  void* handle = handleOf(library, why);
  if (!handle)
    throw Error(purpose + " needs SliceMesh's plugin " + library + ", and " + why);
  dlerror();
  void* address = dlsym(handle, entry);
  if (!address)
    throw Error(purpose + " needs SliceMesh's plugin " + library + ", which has no entry " + entry +
                " (a plugin of another SliceMesh version?)");
  return address;
}

} // namespace slicemesh

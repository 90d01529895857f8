#pragma once

#include <filesystem>
#include <system_error>
#include <vector>

namespace slicemesh::cli
{

/** The folders a run made for its outputs. Unless kept (the run succeeded), those still empty are
 *  removed again when it ends: a run that fails before writing leaves the disk as it found it. */
class MadeFolders
{
public:
  MadeFolders() = default;
  MadeFolders(const MadeFolders&) = delete;
  MadeFolders& operator=(const MadeFolders&) = delete;

  ~MadeFolders()
  {
    if (kept)
      return;
    std::error_code error;
    for (auto folder = made.rbegin(); folder != made.rend(); ++folder) // innermost first
      if (std::filesystem::is_empty(*folder, error) && !error)
        std::filesystem::remove(*folder, error);
  }

  /** Makes `folder` and its missing parents, remembering those it made. */
  void make(const std::filesystem::path& folder, std::error_code& error)
  {
    std::vector<std::filesystem::path> missing; // innermost first
    for (std::filesystem::path place = folder; !place.empty() && !std::filesystem::exists(place, error);
         place = place.parent_path())
    {
      missing.push_back(place);
      if (place == place.parent_path())
        break;
    }
    std::filesystem::create_directories(folder, error);
    if (!error)
      made.insert(made.end(), missing.rbegin(), missing.rend());
  }

  void keep() { kept = true; }

private:
  std::vector<std::filesystem::path> made; // outermost first
  bool kept = false;
};

} // namespace slicemesh::cli

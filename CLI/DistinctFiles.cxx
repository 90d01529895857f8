#include "DistinctFiles.h"

#include "Core/SliceMeshTypes.h"
#include "DetachedDataFiles.h"
#include "FileReplacement.h"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

namespace slicemesh::cli
{
namespace
{

namespace fs = std::filesystem;

/** A file the run reads or writes, and the option that names it. */
struct RunFile
{
  std::string option; ///< "<inputVolume>", "--report"
  std::string path;   ///< as given
  bool written = false;
  fs::path place; ///< placeOf(path)
};

/** Where `path` leads: its links followed (writtenPath: where a write through it goes), made
 *  absolute, "." and ".." resolved, so that "./a.vtp" and "a.vtp" are one place, existing or not. */
fs::path placeOf(const std::string& path)
{
  fs::path place = path;
  try
  {
    place = writtenPath(path);
  }
  catch (const Error&)
  {
    // A loop of links: reading or writing through it fails, with its own message.
  }
  std::error_code error;
  const fs::path absolute = fs::absolute(place, error);
  if (error)
    return place.lexically_normal();
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  return error ? absolute.lexically_normal() : canonical;
}

/** The same place, or one file under two names (a hard link). */
bool sameFile(const fs::path& a, const fs::path& b)
{
  std::error_code ignored;
  return a == b || fs::equivalent(a, b, ignored);
}

/** Inputs first, then outputs; a file not given is left out. */
std::vector<RunFile> runFiles(const PipelineSettings& settings)
{
  const std::string& contours = settings.contours.path;
  std::error_code ignored;
  // The structure set found in the DICOM folder given as the input, or given beside it there.
  const bool inInputFolder = !contours.empty() && fs::is_directory(settings.inputVolume, ignored) &&
                             sameFile(placeOf(contours).parent_path(), placeOf(settings.inputVolume));
  std::vector<RunFile> files = {
    { "<inputVolume>", settings.inputVolume, false },
    { inInputFolder ? "the structure set in <inputVolume>" : "--inputContours",
      contours == settings.inputVolume ? std::string() : contours, false },
    { "--colorTable", settings.multiLabel.colorTable, false },
    { "<outputModel>", settings.outputModel, true },
    { "--report", settings.reportFile, true },
    { "--snapshot", settings.snapshotFile, true },
    { "--returnparameterfile", settings.returnParameterFile, true },
  };
  // A detached header's data are read with it: "data file: payload.stl" is overwritten as surely.
  const std::vector<std::string> dataFiles = detachedDataFiles(settings.inputVolume);
  std::vector<RunFile> data;
  for (const std::string& dataFile : dataFiles)
    data.push_back({ "the data file of <inputVolume>", dataFile, false });
  files.insert(files.begin() + 1, data.begin(), data.end());
  files.erase(std::remove_if(files.begin(), files.end(), [](const RunFile& file) { return file.path.empty(); }),
              files.end());
  for (RunFile& file : files)
    file.place = placeOf(file.path);
  return files;
}

std::string overwrites(const RunFile& earlier)
{
  return earlier.written ? "one output would overwrite the other" : "the output would overwrite the input";
}

} // namespace

void requireDistinctFiles(const PipelineSettings& settings)
{
  const std::vector<RunFile> files = runFiles(settings);
  for (std::size_t later = 0; later < files.size(); ++later)
    for (std::size_t earlier = 0; earlier < later; ++earlier)
      if (files[later].written && sameFile(files[earlier].place, files[later].place))
        throw PipelineFailure(BadArguments, files[earlier].option + " and " + files[later].option +
                                              " are the same file '" + files[earlier].path + "': " +
                                              overwrites(files[earlier]));
}

void requireDistinctStructureFile(const PipelineSettings& settings, const std::string& structureFile,
                                  const std::string& whose)
{
  const fs::path place = placeOf(structureFile);
  for (const RunFile& file : runFiles(settings))
    if (sameFile(file.place, place))
      throw PipelineFailure(BadArguments, whose + "its mesh in --outputDirectory and " + file.option +
                                            " are the same file '" + structureFile + "': " + overwrites(file));
}

} // namespace slicemesh::cli

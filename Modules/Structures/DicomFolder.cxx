#include "DicomFolder.h"

#include "StructureSet.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace slicemesh
{
namespace
{

/** Whether the file starts as DICOM Part 10 does: a 128-byte preamble, then "DICM". */
bool isDicomFile(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  char start[132] = {};
  in.read(start, sizeof start);
  return in.gcount() == static_cast<std::streamsize>(sizeof start) && std::string(start + 128, 4) == "DICM";
}

} // namespace

DicomFolderContents dicomFolderContents(const std::string& folder)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
    if (entry->is_regular_file(error))
      files.push_back(entry->path());
  std::sort(files.begin(), files.end());
  DicomFolderContents contents;
  for (const fs::path& file : files)
  {
    // A structure set by its content, as when given itself: older systems write it without the
    // preamble and "DICM".
    if (detectContourFileKind(file.string()) == ContourFileKind::RTStruct)
      contents.structureSets.push_back(file.string());
    else if (isDicomFile(file))
      ++contents.otherDicomFiles;
  }
  return contents;
}

} // namespace slicemesh

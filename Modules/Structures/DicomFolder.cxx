#include "DicomFolder.h"

#include "StructureSet.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace slicemesh
{
namespace
{

/** What a DICOM Part 10 file's start tells: whether it is DICOM (a 128-byte preamble, then "DICM"),
 *  and whether its File Meta Information names the Segmentation Storage SOP class. */
struct DicomFileStart
{
  bool dicom = false;
  bool segmentation = false;
};

DicomFileStart dicomFileStart(const std::filesystem::path& path)
{
  // The meta information comes first, a few hundred bytes; the class UID is its second element.
  constexpr std::size_t metaBytes = 2048;
  std::ifstream in(path, std::ios::binary);
  std::string start(metaBytes, '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(in.gcount()));
  DicomFileStart result;
  result.dicom = start.size() >= 132 && start.compare(128, 4, "DICM") == 0;
  // The whole UID: "...66.4" and not the start of a longer one ("...66.41").
  const std::string segmentationStorage = "1.2.840.10008.5.1.4.1.1.66.4";
  for (std::size_t at = start.find(segmentationStorage, 132); result.dicom && at != std::string::npos;
       at = start.find(segmentationStorage, at + 1))
  {
    const std::size_t after = at + segmentationStorage.size();
    if (after == start.size() || (start[after] != '.' && !std::isdigit(static_cast<unsigned char>(start[after]))))
      result.segmentation = true;
  }
  return result;
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
    else if (const DicomFileStart start = dicomFileStart(file); start.segmentation)
      contents.segmentations.push_back(file.string());
    else if (start.dicom)
      ++contents.otherDicomFiles;
  }
  return contents;
}

} // namespace slicemesh

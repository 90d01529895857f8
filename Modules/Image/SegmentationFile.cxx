// Which segmentation format a file is, from its first bytes and header fields.
#include "SegmentationFile.h"

#include "DicomImagePlugin.h"

#include "Core/SliceMeshTypes.h"

#include <cctype>
#include <fstream>

namespace slicemesh
{
namespace
{

std::string bytesAt(const std::string& path, std::size_t offset, std::size_t count)
{
  std::ifstream file(path, std::ios::binary);
  std::string bytes(count, '\0');
  if (!file.seekg(static_cast<std::streamoff>(offset)) || !file.read(bytes.data(), static_cast<std::streamsize>(count)))
    return {};
  return bytes;
}

/** "Segment<digits>_...": a key of Slicer's per-segment fields. */
bool isSegmentKey(const std::string& key)
{
  const std::string prefix = "Segment";
  if (key.compare(0, prefix.size(), prefix) != 0)
    return false;
  std::size_t at = prefix.size();
  while (at < key.size() && std::isdigit(static_cast<unsigned char>(key[at])))
    ++at;
  return at > prefix.size() && at < key.size() && key[at] == '_';
}

/** Whether the NRRD header (the text up to the first empty line) has a SegmentN_ key: read here
 *  rather than by ITK, which reads (and may fail on) the voxels of a compressed file too, so that a
 *  damaged segmentation file is still reported as one. */
bool isSlicerSegmentation(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::string line;
  constexpr std::size_t headerLimit = 1 << 20; // a header of thousands of segments is far shorter
  std::size_t read = 0;
  while (std::getline(file, line) && !line.empty() && line != "\r" && (read += line.size()) < headerLimit)
  {
    const std::size_t separator = line.find(":=");
    if (separator != std::string::npos && isSegmentKey(line.substr(0, separator)))
      return true;
  }
  return false;
}

} // namespace

SegmentationFormat segmentationFormatOf(const std::string& path)
{
  if (bytesAt(path, 0, 4) == "NRRD")
    return isSlicerSegmentation(path) ? SegmentationFormat::SlicerNrrd : SegmentationFormat::None;
  if (bytesAt(path, 128, 4) == "DICM")
    return dicomImageFunctions().isSegmentation(path) ? SegmentationFormat::DicomSeg : SegmentationFormat::None;
  return SegmentationFormat::None;
}

SegmentationFile readDicomSegmentation(const std::string& path)
{
  return dicomImageFunctions().readSegmentation(path);
}

SegmentationFile readSegmentationFile(const std::string& path)
{
  switch (segmentationFormatOf(path))
  {
    case SegmentationFormat::SlicerNrrd: return readSlicerSegmentation(path);
    case SegmentationFormat::DicomSeg: return readDicomSegmentation(path);
    case SegmentationFormat::None: break;
  }
  throw Error(path + ": not a segmentation file (3D Slicer .seg.nrrd or DICOM SEG)");
}

} // namespace slicemesh

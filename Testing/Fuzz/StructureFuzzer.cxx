// libFuzzer target on the readers of structure sets and segmentation files: the bytes are a file,
// named as such a file would be (.seg.nrrd, .vtp, .dcm, ...) from its first bytes, and go the way
// the command line takes it: a segmentation file (3D Slicer .seg.nrrd, DICOM SEG) is read and its
// layers indexed; a contour file (RTSTRUCT through DCMTK, JSON, VTK polydata) is read and each
// ROI stacked and repaired. A slicemesh::Error on one line is a fine answer; a crash, a sanitizer
// report, another exception, an error of several lines or a hang is a bug.
//
// Seeds: MakeStructureFuzzSeeds writes one small file of each kind (Utilities/fuzz-smoke.sh).
#include "ContourRepair.h"
#include "Contours/ContourStacking.h"
#include "LabelIndex.h"
#include "SegmentationFile.h"
#include "StructureSet.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{

/** The name a file with these first bytes would have: the readers (ITK's NRRD reader, VTK's
 *  polydata readers) go by the extension as well as the content. */
std::string extensionFor(const std::uint8_t* data, std::size_t size)
{
  const std::string start(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 132));
  if (start.rfind("NRRD", 0) == 0)
    return ".seg.nrrd";
  if (start.rfind("<", 0) == 0)
    return ".vtp";
  if (start.rfind("# vtk", 0) == 0)
    return ".vtk";
  if (start.rfind("{", 0) == 0)
    return ".json";
  return ".dcm";
}

/** A folder of this process's own for the input file, removed when the fuzzer exits. */
struct InputFolder
{
  std::filesystem::path path =
    std::filesystem::temp_directory_path() / ("slicemesh-structure-fuzz-" + std::to_string(::getpid()));
  InputFolder() { std::filesystem::create_directories(path); }
  ~InputFolder()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  InputFolder(const InputFolder&) = delete;
  InputFolder& operator=(const InputFolder&) = delete;
};

void exercise(const std::string& path)
{
  using namespace slicemesh;
  if (segmentationFormatOf(path) != SegmentationFormat::None)
  {
    const SegmentationFile file = readSegmentationFile(path);
    for (const ScalarVolume::Pointer& layer : file.layers)
      indexLabels(layer);
    return;
  }
  if (!detectContourFileKind(path))
    return;
  const StructureSet set = readStructureSet(path);
  for (const PlanarStructure& roi : set.structures)
  {
    try
    {
      ContourStackingOptions options;
      options.fallbackSliceSpacing = 2.0;
      const StackedContours stacked = stackContours(roi.contours, options);
      repairContours(stacked.stack);
    }
    catch (const Error&)
    {
      // An ROI that cannot be stacked is reported and skipped; the others go on.
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const InputFolder folder;
  const std::filesystem::path path = folder.path / ("input" + extensionFor(data, size));
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try
  {
    exercise(path.string());
  }
  catch (const slicemesh::Error& error)
  {
    if (std::string(error.what()).find('\n') != std::string::npos)
      std::abort(); // errors are one line
  }
  std::filesystem::remove(path);
  return 0;
}

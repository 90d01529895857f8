// A DICOM image series through ITK's GDCM reader (part of the plugin SliceMeshImageDicom).
#include "DicomImageReaders.h"

#include "ItkErrorText.h"

#include "Core/SliceMeshTypes.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageSeriesReader.h"

#include <gdcmScanner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

namespace slicemesh
{

namespace
{

/** The files of the largest DICOM image series in the folder, in slice order. */
std::vector<std::string> dicomSeriesFiles(const std::string& folder)
{
  auto names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> fileNames;
  try
  {
    names->SetUseSeriesDetails(true);
    names->SetDirectory(folder);
    const std::vector<std::string>& seriesUIDs = names->GetSeriesUIDs();
    if (seriesUIDs.empty())
      throw Error(folder + ": a directory without a DICOM image series");
    // The series of the most files: an export holds the image series beside one-file objects of
    // their own series (a structure set, a localizer, a dose), which are no volume.
    for (const std::string& uid : seriesUIDs)
    {
      std::vector<std::string> files = names->GetFileNames(uid);
      if (files.size() > fileNames.size())
        fileNames = std::move(files);
    }
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(folder + ": cannot list the DICOM series: " + itkErrorText(error));
  }
  if (fileNames.size() < 2)
    throw Error(folder + ": the DICOM series has a single slice (a 2-D image); SliceMesh needs a 3-D volume");
  return fileNames;
}

/** A multi-valued DICOM decimal string ("a\\b\\c") as its N numbers; empty if it has not N. */
template <std::size_t N>
std::optional<std::array<double, N>> decimals(const char* text)
{
  if (!text)
    return std::nullopt;
  std::string spaced(text);
  std::replace(spaced.begin(), spaced.end(), '\\', ' ');
  std::istringstream in(spaced);
  std::array<double, N> values{};
  for (double& value : values)
    if (!(in >> value) || !std::isfinite(value))
      return std::nullopt;
  return values;
}

std::string fileName(const std::string& path)
{
  return std::filesystem::path(path).filename().string();
}

/** The series reader places the slices evenly between the first and the last: a slice missing from
 *  the export, or slices of two spacings, would shift every slice after it and stretch the mesh
 *  without a word. Each file's Image Position along the normal of the first file's Image
 *  Orientation is checked against its even place; a slice farther than a twentieth of the spacing
 *  from it (a missing slice is half a spacing or more) is refused. Files without these attributes
 *  are left to the reader. */
void requireEvenlySpacedSlices(const std::string& folder, const std::vector<std::string>& files)
{
  const gdcm::Tag positionTag(0x0020, 0x0032), orientationTag(0x0020, 0x0037);
  gdcm::Scanner scanner;
  scanner.AddTag(positionTag);
  scanner.AddTag(orientationTag);
  if (!scanner.Scan(files))
    return;
  const auto orientation = decimals<6>(scanner.GetValue(files.front().c_str(), orientationTag));
  if (!orientation)
    return;
  const std::array<double, 6>& o = *orientation;
  const std::array<double, 3> normal{ o[1] * o[5] - o[2] * o[4], o[2] * o[3] - o[0] * o[5], o[0] * o[4] - o[1] * o[3] };
  std::vector<double> heights;
  for (const std::string& file : files)
  {
    const auto position = decimals<3>(scanner.GetValue(file.c_str(), positionTag));
    if (!position)
      return;
    const std::array<double, 3>& p = *position;
    heights.push_back(p[0] * normal[0] + p[1] * normal[1] + p[2] * normal[2]);
  }
  const std::size_t n = heights.size();
  const double step = (heights.back() - heights.front()) / static_cast<double>(n - 1);
  double worstDeviation = 0.0;
  for (std::size_t k = 1; k < n; ++k)
    worstDeviation = std::max(worstDeviation, std::abs(heights[k] - (heights.front() + static_cast<double>(k) * step)));
  if (!(worstDeviation > 0.05 * std::abs(step)))
    return;
  // Named by the gap between neighbours that differs most from the usual one (the median gap).
  std::vector<double> gaps(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k)
    gaps[k] = std::abs(heights[k + 1] - heights[k]);
  std::vector<double> sorted = gaps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double usual = sorted[sorted.size() / 2];
  std::size_t odd = 0;
  for (std::size_t k = 1; k < gaps.size(); ++k)
    if (std::abs(gaps[k] - usual) > std::abs(gaps[odd] - usual))
      odd = k;
  char text[320];
  std::snprintf(text, sizeof text,
                ": the slices are not evenly spaced: %s and %s are %.3g mm apart where the others are %.3g mm "
                "(a missing slice?); SliceMesh needs the complete, evenly spaced series",
                fileName(files[odd]).c_str(), fileName(files[odd + 1]).c_str(), gaps[odd], usual);
  throw Error(folder + text);
}

} // namespace

ScalarVolume::Pointer readDicomSeriesIn(const std::string& folder, bool voxels)
{
  auto reader = itk::ImageSeriesReader<ScalarVolume>::New();
  auto io = itk::GDCMImageIO::New();
  reader->SetImageIO(io);
  const std::vector<std::string> files = dicomSeriesFiles(folder);
  requireEvenlySpacedSlices(folder, files);
  reader->SetFileNames(files);
  // The series reader orders the slices and takes the spacing between them from their positions.
  if (voxels)
    reader->Update();
  else
    reader->UpdateOutputInformation();
  ScalarVolume::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  // The series' header as one of its files states it: what a slice does not vary (the Frame of
  // Reference) is then known without opening a file again.
  volume->SetMetaDataDictionary(io->GetMetaDataDictionary());
  return volume;
}

} // namespace slicemesh

// A DICOM image series through ITK's GDCM reader (part of the plugin SliceMeshImageDicom).
#include "DicomImageReaders.h"

#include "ItkErrorText.h"

#include "Core/SliceMeshTypes.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageSeriesReader.h"
#include "itkMath.h"
#include "itkMetaDataObject.h"
#include "itkVector.h"

#include <gdcmScanner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <optional>
#include <sstream>

namespace slicemesh
{

namespace
{

/** A DICOM file's Number of Frames (0028,0008); 1 when it does not say. */
long frameCount(const std::string& file)
{
  const gdcm::Tag framesTag(0x0028, 0x0008);
  gdcm::Scanner scanner;
  scanner.AddTag(framesTag);
  const char* text = scanner.Scan({ file }) ? scanner.GetValue(file.c_str(), framesTag) : nullptr;
  return text ? std::max(1L, std::strtol(text, nullptr, 10)) : 1L;
}

std::string fileName(const std::string& path)
{
  return std::filesystem::path(path).filename().string();
}

/** The files of the largest DICOM image series in the folder, in slice order. Where the folder holds
 *  more than one series of several files (two reconstructions of one scan, a CT and an MR), `choice`
 *  says which was taken. */
std::vector<std::string> dicomSeriesFiles(const std::string& folder, std::string& choice)
{
  auto names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> fileNames;
  std::vector<std::pair<std::size_t, std::string>> volumes; // files, first file, of each series of several
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
      if (files.size() > 1)
        volumes.emplace_back(files.size(), fileName(files.front()));
      if (files.size() > fileNames.size())
        fileNames = std::move(files);
    }
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(folder + ": cannot list the DICOM series: " + itkErrorText(error));
  }
  if (volumes.size() > 1)
  {
    std::ostringstream text;
    text << folder << " holds " << volumes.size() << " image series (";
    for (std::size_t v = 0; v < volumes.size(); ++v)
      text << (v ? ", " : "") << volumes[v].first << " files from " << volumes[v].second;
    text << "): meshing the one of " << fileName(fileNames.front())
         << (std::count_if(volumes.begin(), volumes.end(), [&](const auto& v) { return v.first == fileNames.size(); }) > 1
               ? ", the first of the largest"
               : ", the largest")
         << "; give a folder of one series to choose another";
    choice = text.str();
  }
  // One file of several frames (an enhanced, multi-frame CT or MR) is a whole volume by itself.
  if (fileNames.size() < 2 && frameCount(fileNames.front()) < 2)
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

double angleDegrees(const itk::Vector<double, 3>& a, const itk::Vector<double, 3>& b)
{
  return std::acos(std::clamp(a * b / (a.GetNorm() * b.GetNorm()), -1.0, 1.0)) * 180.0 / itk::Math::pi;
}

/** Image Orientation (Patient) is two perpendicular unit vectors (the row's and the column's
 *  direction); a header that says otherwise would be read as a sheared, stretched grid (ITK takes
 *  the vectors as they are). Rounded values (six digits) pass. */
void checkOrientationAxes(const std::string& folder, const std::string& file, const std::array<double, 6>& o)
{
  const double row = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
  const double column = std::sqrt(o[3] * o[3] + o[4] * o[4] + o[5] * o[5]);
  const double cosine = (o[0] * o[3] + o[1] * o[4] + o[2] * o[5]) / (row * column);
  constexpr double tolerance = 1e-3;
  if (std::abs(row - 1.0) <= tolerance && std::abs(column - 1.0) <= tolerance && std::abs(cosine) <= tolerance)
    return;
  char text[320];
  std::snprintf(text, sizeof text,
                ": %s's Image Orientation (Patient) is not two perpendicular unit vectors (lengths %.4g and %.4g, "
                "%.4g degrees apart); a damaged header",
                fileName(file).c_str(), row, column,
                std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / itk::Math::pi);
  throw Error(folder + text);
}

/** No two images at one position along the slices' normal (`heights`, in the files' order): the
 *  echoes, phases or repeats of one scan share a series and its positions, and would be stacked
 *  as slices. */
void checkOneImagePerPosition(const std::string& folder, const std::vector<std::string>& files,
                              const std::vector<double>& heights)
{
  const double extent = std::abs(heights.back() - heights.front());
  const double mean = extent / static_cast<double>(heights.size() - 1);
  std::vector<std::size_t> order(heights.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return heights[a] < heights[b]; });
  for (std::size_t k = 0; k + 1 < order.size(); ++k)
  {
    if (heights[order[k + 1]] - heights[order[k]] > 1e-3 * mean)
      continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  ": %s and %s are at one position (echoes, phases or repeats of one scan?); SliceMesh needs "
                  "one image per slice position",
                  fileName(files[order[k]]).c_str(), fileName(files[order[k + 1]]).c_str());
    throw Error(folder + text);
  }
}

/** The step from one slice's Image Position to the next's, checked. The series reader places every
 *  slice in the first one's orientation, evenly between the first and the last: slices of another
 *  orientation (a three-plane localizer shares one series) would be put where they are not, and a
 *  slice missing from the export, or slices of two spacings, would shift every slice after it and
 *  stretch the mesh without a word. So every file's Image Orientation must be the first's, and its
 *  Image Position along the normal within a twentieth of the spacing of its even place (a missing
 *  slice is half a spacing or more). Empty when the files lack these attributes (left to the
 *  reader). */
std::optional<std::array<double, 3>> checkedSliceStep(const std::string& folder, const std::vector<std::string>& files)
{
  const gdcm::Tag positionTag(0x0020, 0x0032), orientationTag(0x0020, 0x0037);
  gdcm::Scanner scanner;
  scanner.AddTag(positionTag);
  scanner.AddTag(orientationTag);
  if (!scanner.Scan(files))
    return std::nullopt;
  const auto orientation = decimals<6>(scanner.GetValue(files.front().c_str(), orientationTag));
  if (!orientation)
    return std::nullopt;
  const std::array<double, 6>& o = *orientation;
  checkOrientationAxes(folder, files.front(), o);
  for (const std::string& file : files)
  {
    const auto other = decimals<6>(scanner.GetValue(file.c_str(), orientationTag));
    if (!other)
      continue;
    using Direction = itk::Vector<double, 3>; // the row's (values 0-2) and the column's (3-5)
    const double turn = std::max(angleDegrees(Direction(&o[0]), Direction(&(*other)[0])),
                                 angleDegrees(Direction(&o[3]), Direction(&(*other)[3])));
    // Exports that round the direction cosines to four or five digits turn slices by a few
    // hundredths of a degree; at 0.05 degrees the far corner of a 500 mm slice moves 0.2 mm.
    if (turn > 0.05)
    {
      char text[320];
      std::snprintf(text, sizeof text,
                    ": the slices are not all of one orientation: %s is turned %.3g degrees from %s; SliceMesh needs "
                    "one series of parallel slices",
                    fileName(file).c_str(), turn, fileName(files.front()).c_str());
      throw Error(folder + text);
    }
  }
  const std::array<double, 3> normal{ o[1] * o[5] - o[2] * o[4], o[2] * o[3] - o[0] * o[5], o[0] * o[4] - o[1] * o[3] };
  std::vector<std::array<double, 3>> positions;
  std::vector<double> heights;
  for (const std::string& file : files)
  {
    const auto position = decimals<3>(scanner.GetValue(file.c_str(), positionTag));
    if (!position)
      return std::nullopt;
    const std::array<double, 3>& p = *position;
    positions.push_back(p);
    heights.push_back(p[0] * normal[0] + p[1] * normal[1] + p[2] * normal[2]);
  }
  const std::size_t n = heights.size();
  checkOneImagePerPosition(folder, files, heights);
  std::array<double, 3> step{};
  for (int a = 0; a < 3; ++a)
    step[a] = (positions.back()[a] - positions.front()[a]) / static_cast<double>(n - 1);
  const double spacing = (heights.back() - heights.front()) / static_cast<double>(n - 1);
  double worstDeviation = 0.0;
  for (std::size_t k = 1; k < n; ++k)
    worstDeviation = std::max(worstDeviation, std::abs(heights[k] - (heights.front() + static_cast<double>(k) * spacing)));
  if (!(worstDeviation > 0.05 * std::abs(spacing)))
    return step;
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

/** A gantry-tilted series: each slice is shifted in its plane from the one before, so the voxel
 *  grid is sheared. The series reader stacks the slices along their normal, the distance between
 *  positions apart (too far, and without the shift: the mesh would be stretched and out of place
 *  by up to the tilt's whole shift); the third axis is made the step between positions instead,
 *  which puts every voxel where it was scanned. A shift under a thousandth of the step (rounded
 *  positions) is left alone. */
void followTiltedSlices(ScalarVolume* volume, const std::array<double, 3>& step)
{
  const double length = std::sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
  if (!(length > 0.0))
    return;
  ScalarVolume::DirectionType direction = volume->GetDirection();
  double along = 0.0;
  for (unsigned int row = 0; row < 3; ++row)
    along += step[row] * direction[row][2];
  const double across = std::sqrt(std::max(0.0, length * length - along * along));
  if (!(across > 1e-3 * length))
    return;
  for (unsigned int row = 0; row < 3; ++row)
    direction[row][2] = step[row] / length;
  ScalarVolume::SpacingType spacing = volume->GetSpacing();
  spacing[2] = length;
  volume->SetDirection(direction);
  volume->SetSpacing(spacing);
}

} // namespace

ScalarVolume::Pointer readDicomSeriesIn(const std::string& folder, bool voxels)
{
  auto reader = itk::ImageSeriesReader<ScalarVolume>::New();
  auto io = itk::GDCMImageIO::New();
  reader->SetImageIO(io);
  std::string choice;
  const std::vector<std::string> files = dicomSeriesFiles(folder, choice);
  const std::optional<std::array<double, 3>> step =
    files.size() > 1 ? checkedSliceStep(folder, files) : std::nullopt;
  reader->SetFileNames(files);
  // The series reader orders the slices and takes the spacing between them from their positions.
  if (voxels)
    reader->Update();
  else
    reader->UpdateOutputInformation();
  ScalarVolume::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  if (step)
    followTiltedSlices(volume, *step);
  // The series' header as one of its files states it: what a slice does not vary (the Frame of
  // Reference) is then known without opening a file again.
  volume->SetMetaDataDictionary(io->GetMetaDataDictionary());
  if (!choice.empty())
    itk::EncapsulateMetaData<std::string>(volume->GetMetaDataDictionary(), seriesChoiceKey, choice);
  return volume;
}

} // namespace slicemesh

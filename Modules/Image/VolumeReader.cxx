// Reading a volume with ITK, and turning everything that can go wrong on the way into one
// slicemesh::Error with a one-line message that names the input.
#include "VolumeReader.h"

#include "SliceMeshTypes.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageFileReader.h"
#include "itkImageIOFactory.h"
#include "itkImageSeriesReader.h"

#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace slicemesh
{
namespace
{

/** ITK's exception text spans several lines (file, line, location, description); keep the
 *  description, on one line, short enough to read in a terminal. */
std::string oneLine(const std::string& text)
{
  std::string line;
  bool pendingSpace = false;
  for (char c : text)
  {
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ')
    {
      pendingSpace = !line.empty();
      continue;
    }
    if (pendingSpace)
      line += ' ';
    pendingSpace = false;
    line += c;
  }
  constexpr std::size_t maxLength = 200;
  if (line.size() > maxLength)
    line = line.substr(0, maxLength - 3) + "...";
  return line.empty() ? std::string("unknown ITK error") : line;
}

std::string describe(const itk::ExceptionObject& error)
{
  const char* description = error.GetDescription();
  return oneLine(description && *description ? description : error.what());
}

/** The geometry checks every reader path shares: a mesh cannot be placed without a usable
 *  spacing and an invertible direction matrix. */
void checkGeometry(const std::string& path, const double spacing[3], const double direction[3][3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!std::isfinite(spacing[axis]) || spacing[axis] <= 0.0)
    {
      std::ostringstream message;
      message << path << ": spacing along axis " << axis << " is " << spacing[axis]
              << "; SliceMesh needs positive, finite voxel spacing";
      throw Error(message.str());
    }
  }
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      if (!std::isfinite(direction[row][column]))
        throw Error(path + ": the direction matrix has a non-finite entry");
  const double (*d)[3] = direction;
  const double determinant = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                             d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                             d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  if (std::abs(determinant) < 1e-6)
  {
    std::ostringstream message;
    message << path << ": the direction matrix is singular (determinant " << determinant
            << "); the image axes do not span 3-D space";
    throw Error(message.str());
  }
}

void checkGeometry(const std::string& path, const ScalarVolume* volume)
{
  double spacing[3];
  double direction[3][3];
  for (int i = 0; i < 3; ++i)
  {
    spacing[i] = volume->GetSpacing()[i];
    for (int j = 0; j < 3; ++j)
      direction[i][j] = volume->GetDirection()[i][j];
  }
  checkGeometry(path, spacing, direction);
}

/** Checks what the file header says before any voxel is read: dimension, components, geometry. */
void checkHeader(const std::string& path, const itk::ImageIOBase* io)
{
  const unsigned int dimension = io->GetNumberOfDimensions();
  // A 4-D image with a single time point is a 3-D volume in a 4-D container (common in NIfTI).
  const bool singleton4D = dimension == 4 && io->GetDimensions(3) == 1;
  if (dimension != 3 && !singleton4D)
  {
    std::ostringstream message;
    message << path << ": a " << dimension << "-D image; SliceMesh needs a 3-D volume";
    throw Error(message.str());
  }
  if (io->GetNumberOfComponents() != 1)
  {
    std::ostringstream message;
    message << path << ": " << io->GetNumberOfComponents()
            << " components per voxel; SliceMesh needs a scalar volume";
    throw Error(message.str());
  }
  double spacing[3];
  double direction[3][3];
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    spacing[axis] = io->GetSpacing(axis);
    const std::vector<double> column = io->GetDirection(axis);
    for (unsigned int row = 0; row < 3; ++row)
      direction[row][axis] = row < column.size() ? column[row] : 0.0;
  }
  checkGeometry(path, spacing, direction);
}

/** Whether a gzip file decompresses to its end. ITK 5.2's NIfTI reader accepts a truncated .nii.gz
 *  without complaint (the missing voxels come out as whatever was in memory), so the stream is
 *  checked first. Costs one extra decompression, cheap next to what follows. */
void checkGzipStream(const std::string& path)
{
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file)
    throw Error(path + ": cannot open the file");
  std::vector<char> chunk(1 << 18);
  int read = 0;
  while ((read = gzread(file, chunk.data(), static_cast<unsigned int>(chunk.size()))) > 0)
  {
  }
  // A stream that stops early ends with 0 bytes read and Z_BUF_ERROR, not with -1.
  int code = Z_OK;
  std::string reason = gzerror(file, &code);
  if (reason.compare(0, path.size() + 2, path + ": ") == 0)
    reason.erase(0, path.size() + 2); // zlib names the file too
  gzclose(file);
  if (read < 0 || code != Z_OK)
    throw Error(path + ": a damaged or truncated gzip file (" + oneLine(reason) + ")");
}

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

ScalarVolume::Pointer readImageFile(const std::string& path)
{
  if (endsWith(path, ".gz") || endsWith(path, ".GZ"))
    checkGzipStream(path);

  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::FileModeEnum::ReadMode);
  if (!io)
    throw Error(path + ": not an image file SliceMesh can read (NIfTI, NRRD, MetaImage, DICOM)");
  try
  {
    io->SetFileName(path);
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot read the image header: " + describe(error));
  }
  checkHeader(path, io);

  using Reader = itk::ImageFileReader<ScalarVolume>;
  auto reader = Reader::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot read the voxels: " + describe(error));
  }
  ScalarVolume::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();

  if (io->GetNumberOfDimensions() == 4)
  {
    // ITK's reader falls back to the identity direction when it drops a dimension; the first
    // three axes of the file still say where the volume is.
    ScalarVolume::DirectionType direction;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      const std::vector<double> column = io->GetDirection(axis);
      for (unsigned int row = 0; row < 3; ++row)
        direction[row][axis] = column[row];
    }
    volume->SetDirection(direction);
  }
  checkGeometry(path, volume);
  return volume;
}

ScalarVolume::Pointer readDicomSeries(const std::string& directory)
{
  auto names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> fileNames;
  try
  {
    names->SetUseSeriesDetails(true);
    names->SetDirectory(directory);
    const std::vector<std::string>& seriesUIDs = names->GetSeriesUIDs();
    if (seriesUIDs.empty())
      throw Error(directory + ": a directory without a DICOM image series");
    fileNames = names->GetFileNames(seriesUIDs.front());
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(directory + ": cannot list the DICOM series: " + describe(error));
  }
  if (fileNames.size() < 2)
    throw Error(directory + ": the DICOM series has a single slice (a 2-D image); SliceMesh needs a 3-D volume");

  using Reader = itk::ImageSeriesReader<ScalarVolume>;
  auto reader = Reader::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(fileNames);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(directory + ": cannot read the DICOM series: " + describe(error));
  }
  ScalarVolume::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  checkGeometry(directory, volume);
  return volume;
}

} // namespace

ScalarVolume::Pointer readVolume(const std::string& path)
{
  std::error_code ignored;
  const std::filesystem::path file(path);
  if (!std::filesystem::exists(file, ignored))
    throw Error(path + ": no such file or directory");
  if (std::filesystem::is_directory(file, ignored))
    return readDicomSeries(path);
  return readImageFile(path);
}

} // namespace slicemesh

// Reading a volume with ITK, and turning everything that can go wrong on the way into one
// slicemesh::Error with a one-line message that names the input.
#include "VolumeReader.h"

#include "Core/Determinant3.h"

#include "DicomImagePlugin.h"
#include "ItkErrorText.h"
#include "MemoryBudget.h"
#include "Nifti1Header.h"
#include "RawVoxelBytes.h"
#include "ReaderSpaceCorrection.h"
#include "SilencedStandardError.h"

#include "Core/Lowercase.h"
#include "Core/MeasureText.h"
#include "Core/SliceMeshTypes.h"

#include "itkImageFileReader.h"
#include "itkMetaImageIO.h"
#include "itkImageIOFactory.h"
#include "itkMetaDataObject.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

/** Several lines (MetaIO's complaints) on one, short enough to read in a terminal. */
std::string oneLine(const std::string& text)
{
  std::string line = collapsedWhitespace(text);
  constexpr std::size_t maxLength = 200;
  if (line.size() > maxLength)
    line = line.substr(0, maxLength - 3) + "...";
  return line.empty() ? std::string("unknown error") : line;
}

/** The geometry checks every reader path shares: a mesh cannot be placed without a usable
 *  spacing and an invertible direction matrix. */
/** The voxel sides SliceMesh meshes (mm), and how far apart they may be: outside these the contours
 *  degenerate (points that coincide in the tiling, memory estimates beyond any machine) or a run
 *  ends after minutes with a surface that has lost its shape (a 1 x 1 x 1000 mm grid). */
constexpr double smallestSpacing = 1e-6, largestSpacing = 1e6, largestSpacingRatio = 200.0;

/** How many voxel sides the coordinates may reach: the physical points are doubles, and the mesh is
 *  written in single precision by most formats, so a grid whose origin lies a billion voxels away
 *  would land flat, every vertex on the same coordinate. */
constexpr double farthestInVoxels = 1e9;

void checkGeometry(const std::string& path, const double spacing[3], const double direction[3][3],
                   const double origin[3], const std::size_t size[3])
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
    if (spacing[axis] < smallestSpacing || spacing[axis] > largestSpacing)
    {
      std::ostringstream message;
      message << path << ": spacing along axis " << axis << " is " << spacing[axis] << " mm; SliceMesh meshes voxel sides from "
              << smallestSpacing << " to " << largestSpacing << " mm";
      throw Error(message.str());
    }
    if (!std::isfinite(origin[axis]))
      throw Error(path + ": the origin has a non-finite coordinate");
  }
  const double finest = std::min({ spacing[0], spacing[1], spacing[2] });
  const double coarsest = std::max({ spacing[0], spacing[1], spacing[2] });
  if (coarsest > largestSpacingRatio * finest)
  {
    std::ostringstream message;
    message << path << ": voxel sides of " << finest << " and " << coarsest << " mm; SliceMesh meshes grids whose sides are at most "
            << largestSpacingRatio << " times apart";
    throw Error(message.str());
  }
  double farthest = 0.0; // from 0, bounding the coordinates of every voxel
  for (int axis = 0; axis < 3; ++axis)
    farthest += std::abs(origin[axis]) + static_cast<double>(size[axis]) * spacing[axis];
  if (farthest > farthestInVoxels * finest)
  {
    std::ostringstream message;
    message << path << ": its voxels lie up to " << farthest << " mm from the origin of the coordinates, more than "
            << farthestInVoxels << " voxel sides (" << finest << " mm); their coordinates cannot be told apart";
    throw Error(message.str());
  }
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      if (!std::isfinite(direction[row][column]))
        throw Error(path + ": the direction matrix has a non-finite entry");
  const double determinant = determinant3(direction);
  if (std::abs(determinant) < 1e-6)
  {
    std::ostringstream message;
    message << path << ": the direction matrix is singular (determinant " << determinant
            << "); the image axes do not span 3-D space";
    throw Error(message.str());
  }
}

/** The Frame of Reference UID a DICOM header holds (GDCM's key), without its padding (spaces, a
 *  NUL); empty if none. */
std::string frameOfReferenceIn(const itk::MetaDataDictionary& header)
{
  std::string uid;
  if (!itk::ExposeMetaData<std::string>(header, "0020|0052", uid))
    return {};
  const std::string padding(" \0", 2);
  const auto first = uid.find_first_not_of(padding);
  if (first == std::string::npos)
    return {};
  return uid.substr(first, uid.find_last_not_of(padding) - first + 1);
}

/** The first three axes' spacing and direction as the header states them, checked. */
VolumeGeometry checkHeaderGeometry(const std::string& path, const itk::ImageIOBase* io)
{
  VolumeGeometry geometry;
  double spacing[3], origin[3];
  std::size_t size[3];
  double direction[3][3];
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    spacing[axis] = geometry.spacing[axis] = io->GetSpacing(axis);
    origin[axis] = geometry.origin[axis] = io->GetOrigin(axis);
    size[axis] = io->GetDimensions(axis);
    const std::vector<double> column = io->GetDirection(axis);
    for (unsigned int row = 0; row < 3; ++row)
      direction[row][axis] = geometry.direction[row][axis] = row < column.size() ? column[row] : 0.0;
  }
  checkGeometry(path, spacing, direction, origin, size);
  return geometry;
}

/** Whether readStoredVolume keeps a file's voxels as they are stored: integers of one to four bytes
 *  (StoredVolume's alternatives), which float would make larger or, past 2^24, round. */
bool keptAsStored(itk::IOComponentEnum component)
{
  return component == itk::IOComponentEnum::UCHAR || component == itk::IOComponentEnum::CHAR ||
         component == itk::IOComponentEnum::USHORT || component == itk::IOComponentEnum::SHORT ||
         component == itk::IOComponentEnum::UINT || component == itk::IOComponentEnum::INT;
}

/** Checks what the file header says before any voxel is read: dimension, components, geometry.
 *  `asStored`: the voxels will be read as stored where keptAsStored says so (readStoredVolume),
 *  else as float (readVolume). */
void checkHeader(const std::string& path, const itk::ImageIOBase* io, bool asStored)
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
  if (io->GetComponentType() == itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE)
    throw Error(path + ": its voxel type is not one SliceMesh can read (integers or floats of 1 to 8 bytes)");
  // Memory, before a voxel is allocated: the volume as it will be held (as stored; or as float,
  // beside the file's own voxels while ITK converts them), the mask and the work on them.
  double voxels = 1.0;
  for (unsigned int axis = 0; axis < 3; ++axis)
    voxels *= static_cast<double>(io->GetDimensions(axis));
  const double fileBytesPerVoxel = static_cast<double>(io->GetComponentSize());
  const double volumeBytesPerVoxel = asStored && keptAsStored(io->GetComponentType()) ? fileBytesPerVoxel
                                     : io->GetComponentType() == itk::IOComponentEnum::FLOAT
                                       ? 4.0
                                       : 4.0 + fileBytesPerVoxel;
  {
    std::ostringstream what;
    what << path << ": a " << io->GetDimensions(0) << " x " << io->GetDimensions(1) << " x " << io->GetDimensions(2)
         << " volume";
    checkMemoryBudget(what.str(), runMemoryBytes(voxels, volumeBytesPerVoxel));
  }

  checkHeaderGeometry(path, io);
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

/** Where a detached header's data file `named` lies: as named if absolute, else beside the header. */
std::filesystem::path dataFilePath(const std::string& header, const std::string& named)
{
  return std::filesystem::path(named).is_absolute() ? std::filesystem::path(named)
                                                    : std::filesystem::path(header).parent_path() / named;
}

/** A MetaImage header's "ElementDataFile = LIST [kD]" names one file per k-D block, a line each after
 *  it: as many as the sizes beyond the first k (k = NDims - 1 unless given) make, each of which must
 *  exist. MetaIO reads a shorter list without complaint and leaves the rest of the volume as
 *  whatever memory held. `header`: the lines of the .mhd file; `at`: the LIST line's index. */
void checkMetaImageList(const std::string& path, const std::vector<std::string>& header, std::size_t at)
{
  int dimensions = 0;
  std::vector<double> sizes;
  for (std::size_t i = 0; i < at; ++i)
  {
    const std::string& line = header[i];
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos)
      continue;
    std::string key = line.substr(0, equals);
    key.erase(key.find_last_not_of(" \t") + 1);
    std::istringstream values(line.substr(equals + 1));
    if (key == "NDims")
      values >> dimensions;
    else if (key == "DimSize")
      for (double size; values >> size;)
        sizes.push_back(size);
  }
  std::istringstream list(header[at].substr(header[at].find("LIST") + 4));
  int blockDimensions = dimensions - 1;
  std::string given;
  if (list >> given && given.size() >= 2 && (given.back() == 'D' || given.back() == 'd'))
    blockDimensions = std::atoi(given.c_str());
  if (dimensions < 1 || static_cast<int>(sizes.size()) < dimensions || blockDimensions < 1 || blockDimensions > dimensions)
    return; // MetaIO says what is wrong with the header
  double expected = 1.0;
  for (int axis = blockDimensions; axis < dimensions; ++axis)
    expected *= sizes[static_cast<std::size_t>(axis)];
  std::vector<std::string> files;
  for (std::size_t i = at + 1; i < header.size(); ++i)
  {
    std::string name = header[i];
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (!name.empty())
      files.push_back(name);
  }
  if (static_cast<double>(files.size()) < expected)
  {
    std::ostringstream message;
    message << path << ": its ElementDataFile LIST names " << files.size() << " files where its sizes need "
            << measureText(expected, 0);
    throw Error(message.str());
  }
  for (const std::string& name : files)
  {
    const std::filesystem::path data = dataFilePath(path, name);
    if (!std::filesystem::exists(data))
      throw Error(path + ": its voxels are partly in '" + name + "', which does not exist (" + data.string() + ")");
  }
}

/** A detached header's (MetaImage .mhd, NRRD .nhdr) data file, when it names one file, must exist:
 *  the readers' own message names the header as the file that "cannot be read". A MetaImage list
 *  is checked by checkMetaImageList; NRRD's lists, patterns and LOCAL data are left to the readers. */
void checkDetachedDataFile(const std::string& path)
{
  const bool meta = endsInAnyCase(path, ".mhd"), nrrd = endsInAnyCase(path, ".nhdr");
  if (!meta && !nrrd)
    return;
  std::ifstream in(path);
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);)
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    header.push_back(line);
  }
  for (std::size_t at = 0; at < header.size(); ++at)
  {
    const std::string& line = header[at];
    std::string named;
    if (meta && line.rfind("ElementDataFile", 0) == 0 && line.find('=') != std::string::npos)
      named = line.substr(line.find('=') + 1);
    else if (nrrd && (line.rfind("data file:", 0) == 0 || line.rfind("datafile:", 0) == 0))
      named = line.substr(line.find(':') + 1);
    else
      continue;
    named.erase(0, named.find_first_not_of(" \t"));
    named.erase(named.find_last_not_of(" \t") + 1);
    if (meta && named.rfind("LIST", 0) == 0)
      return checkMetaImageList(path, header, at);
    if (named.empty() || named == "LOCAL" || named.rfind("LIST", 0) == 0 || named.find(' ') != std::string::npos ||
        named.find('%') != std::string::npos)
      return;
    const std::filesystem::path data = dataFilePath(path, named);
    if (!std::filesystem::exists(data))
      throw Error(path + ": its voxels are in '" + named + "', which does not exist (" + data.string() + ")");
    return;
  }
}

/** A MetaImage's geometry fields must hold finite numbers: MetaIO refuses a "nan" or "inf" there
 *  with "File cannot be read ... Reason: Invalid argument", as if the file could not be opened.
 *  The header is text up to its ElementDataFile line (the voxels of a .mha follow it). */
void checkMetaImageGeometry(const std::string& path)
{
  if (!endsInAnyCase(path, ".mha") && !endsInAnyCase(path, ".mhd"))
    return;
  // The fields MetaIO reads as numbers that place the voxels (Offset has two other names).
  static const std::set<std::string> geometry = { "ElementSpacing", "ElementSize", "Offset", "Origin", "Position",
                                                  "TransformMatrix", "Rotation", "Orientation", "CenterOfRotation" };
  // A header is a few hundred bytes: a file that is no MetaImage is not read whole.
  constexpr std::size_t longestHeader = 1 << 16;
  std::ifstream in(path, std::ios::binary);
  std::string text(longestHeader, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() == longestHeader)
    text.erase(text.find_last_of('\n') + 1); // a line cut off would read as another value
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos)
      continue;
    std::string key = line.substr(0, equals);
    key.erase(0, key.find_first_not_of(" \t"));
    key.erase(key.find_last_not_of(" \t") + 1);
    if (key == "ElementDataFile")
      return;
    if (!geometry.count(key))
      continue;
    std::istringstream values(line.substr(equals + 1));
    for (std::string value; values >> value;)
    {
      char* end = nullptr;
      const double number = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !std::isfinite(number))
        throw Error(path + ": its " + key + " holds '" + oneLine(value) + "', which is not a finite number");
    }
  }
}

/** Catches what a reader writes to std::cerr while it runs: MetaIO reports a short read of the
 *  voxels there (several lines) and carries on with garbage. Restores std::cerr when it goes. */
class CapturedErrorStream
{
public:
  CapturedErrorStream()
    : m_Saved(std::cerr.rdbuf(m_Text.rdbuf()))
  {
  }
  ~CapturedErrorStream() { std::cerr.rdbuf(m_Saved); }
  CapturedErrorStream(const CapturedErrorStream&) = delete;
  CapturedErrorStream& operator=(const CapturedErrorStream&) = delete;
  std::string text() const { return m_Text.str(); }

private:
  std::ostringstream m_Text;
  std::streambuf*    m_Saved;
};

/** An uncompressed single-file NIfTI holds its voxels after a header of at least 352 bytes; ITK 5.2
 *  reads a truncated one without complaint (the missing voxels come out as zeros). For NIfTI-1 the
 *  size is the stored one (bitpix, vox_offset): ITK reports a scaled file (scl_slope) as float
 *  whatever it stores; `header` is the file's (readNifti1Header). Other headers (NIfTI-2) are held
 *  to ITK's size of the voxels. */
void checkNiftiFileSize(const std::string& path, const itk::ImageIOBase* io, const std::optional<Nifti1Header>& header)
{
  if (!endsInAnyCase(path, ".nii"))
    return;
  std::error_code error;
  const auto fileSize = std::filesystem::file_size(path, error);
  if (error)
    return;
  double needed = 352.0 + static_cast<double>(io->GetImageSizeInBytes());
  if (header)
  {
    if (header->dim[0] < 1 || header->dim[0] > 7 || header->bitpix <= 0)
      return; // ITK says what is wrong with the header
    double voxels = 1.0;
    for (int axis = 1; axis <= header->dim[0]; ++axis)
      voxels *= std::max<std::int16_t>(1, header->dim[static_cast<std::size_t>(axis)]);
    needed = std::max(352.0, static_cast<double>(header->voxOffset)) + voxels * header->bitpix / 8.0;
  }
  if (static_cast<double>(fileSize) < needed)
  {
    std::ostringstream message; // `needed` may be beyond any integer type (a damaged header): printed as a double
    message << path << ": a truncated NIfTI file (" << fileSize << " bytes; its header promises at least "
            << measureText(needed, 0) << ")";
    throw Error(message.str());
  }
}

/** NIfTI-1 stores the spacing as pixdim[1..3]; the NIfTI library (and so ITK) silently replaces a zero
 *  or negative one by 1 mm, which would mesh at a made-up scale. Those three floats of the file's
 *  `header` (readNifti1Header; empty for another file) are refused unless positive and finite. NIfTI-2 and other formats are left
 *  to ITK's own values, checked by checkGeometry. */
void checkNiftiSpacing(const std::string& path, const std::optional<Nifti1Header>& header)
{
  if (!header)
    return; // ITK reports the short file, or it is not NIfTI-1
  for (int axis = 0; axis < 3; ++axis)
  {
    const float spacing = header->pixdim[static_cast<std::size_t>(axis) + 1];
    if (!std::isfinite(spacing) || spacing <= 0.0f)
    {
      std::ostringstream message;
      message << path << ": spacing along axis " << axis << " is " << spacing
              << " in the NIfTI header; SliceMesh needs positive, finite voxel spacing";
      throw Error(message.str());
    }
  }
}

/** The orientation a NIfTI-1 header's codes put in use (the quaternion and offset when qform_code
 *  is set, the affine rows when sform_code is), and where its voxels start, must be finite: ITK
 *  aborts the process on a NaN or infinite affine (an assertion in its decomposition), takes a NaN
 *  offset for 0 and reads a negative vox_offset bytes before the voxels. `header`: the file's
 *  (readNifti1Header; empty for another file). */
void checkNiftiOrientation(const std::string& path, const std::optional<Nifti1Header>& header)
{
  if (!header)
    return;
  const auto finite = [](const auto& values) {
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
  };
  if (header->qformCode > 0 && !finite(header->quaternion))
    throw Error(path + ": the NIfTI header's quaternion orientation (qform) holds a value that is not a finite number");
  if (header->sformCode > 0 && !finite(header->sform))
    throw Error(path + ": the NIfTI header's affine orientation (sform) holds a value that is not a finite number");
  if (!std::isfinite(header->voxOffset) || header->voxOffset < 0.0f)
    throw Error(path + ": the NIfTI header's vox_offset (where the voxels start) is not a non-negative number");
}

/** GDCM aborts the process (a failed assertion) on a DICOM file whose File Meta Information is cut
 *  off, names a value representation that does not exist, or gives an element a length beyond the
 *  file, before ITK could report anything: such a file is refused here. The meta group (0002,xxxx)
 *  follows the 128-byte preamble and "DICM", always in explicit VR little endian; the file must hold
 *  it and at least one element of the data set after it. */
void checkDicomFileMeta(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 132> preamble{};
  in.read(reinterpret_cast<char*>(preamble.data()), static_cast<std::streamsize>(preamble.size()));
  if (in.gcount() < 132 || std::memcmp(preamble.data() + 128, "DICM", 4) != 0)
    return; // not a DICOM file with a preamble
  std::error_code error;
  const auto fileSize = std::filesystem::file_size(path, error);
  if (error)
    return;
  const auto damaged = [&](const std::string& why) {
    return Error(path + ": a damaged DICOM file (" + why + ")");
  };
  const auto cutOff = [&] {
    return Error(path + ": a truncated DICOM file (" + std::to_string(fileSize) + " bytes, cut off in its File Meta Information)");
  };
  // Value representations whose length takes 4 bytes after 2 reserved ones; the others take 2.
  static const std::set<std::string> longLength = { "OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV" };
  static const std::set<std::string> shortLength = { "AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL", "IS",
                                                     "LO", "LT", "PN", "SH", "SL", "SS", "ST", "TM", "UI", "UL", "US" };
  std::uint64_t at = 132;
  for (;;)
  {
    std::array<unsigned char, 12> element{};
    in.read(reinterpret_cast<char*>(element.data()), 8);
    if (in.gcount() < 8)
      throw cutOff();
    if (element[0] != 0x02 || element[1] != 0x00)
      return; // the data set begins
    const std::string vr(reinterpret_cast<const char*>(element.data()) + 4, 2);
    std::uint64_t length = 0;
    std::uint64_t value = at + 8;
    if (longLength.count(vr))
    {
      in.read(reinterpret_cast<char*>(element.data()) + 8, 4);
      if (in.gcount() < 4)
        throw cutOff();
      length = static_cast<std::uint64_t>(element[8]) | static_cast<std::uint64_t>(element[9]) << 8 |
               static_cast<std::uint64_t>(element[10]) << 16 | static_cast<std::uint64_t>(element[11]) << 24;
      value = at + 12;
    }
    else if (shortLength.count(vr))
      length = static_cast<std::uint64_t>(element[6]) | static_cast<std::uint64_t>(element[7]) << 8;
    else
      throw damaged("its File Meta Information names the value representation '" + oneLine(vr) + "', which does not exist");
    // One element of the data set at least (8 bytes) follows the meta group.
    if (length == 0xFFFFFFFFu || value + length + 8 > fileSize)
      throw Error(path + ": a truncated DICOM file (" + std::to_string(fileSize) +
                  " bytes; an element of its File Meta Information needs " + std::to_string(value + length + 8) + ")");
    // The group's length, (0002,0000) UL, promises where the data set begins.
    if (element[2] == 0x00 && element[3] == 0x00 && vr == "UL" && length == 4)
    {
      std::array<unsigned char, 4> bytes{};
      in.read(reinterpret_cast<char*>(bytes.data()), 4);
      const std::uint64_t groupEnd = value + 4 + (static_cast<std::uint64_t>(bytes[0]) | static_cast<std::uint64_t>(bytes[1]) << 8 |
                                                  static_cast<std::uint64_t>(bytes[2]) << 16 | static_cast<std::uint64_t>(bytes[3]) << 24);
      if (groupEnd + 8 > fileSize)
        throw Error(path + ": a truncated DICOM file (" + std::to_string(fileSize) + " bytes; its header needs at least " +
                    std::to_string(groupEnd + 8) + ")");
    }
    at = value + length;
    in.seekg(static_cast<std::streamoff>(at));
  }
}

/** The header of an image file through the ImageIO ITK picks for it. */
itk::ImageIOBase::Pointer readImageHeader(const std::string& path)
{
  checkDicomFileMeta(path);
  checkMetaImageGeometry(path);
  const std::optional<Nifti1Header> nifti = readNifti1Header(path);
  checkNiftiOrientation(path, nifti);
  constexpr auto reading = itk::ImageIOFactory::FileModeEnum::ReadMode;
  // The readers ITK tries on the file, and the one that reads its header, speak on the standard
  // error of a damaged file; ITK's exception (or SliceMesh's own message below) says it in one line.
  const SilencedStandardError silenced;
  itk::ImageIOBase::Pointer io = itk::ImageIOFactory::CreateImageIO(path.c_str(), reading);
  const std::string unreadable = path + ": not an image file SliceMesh can read (NIfTI, NRRD, MetaImage, DICOM)";
  if (!io)
  {
    // Perhaps a single DICOM image: its reader (GDCM) comes with the DICOM plugin.
    try
    {
      dicomImageFunctions();
    }
    catch (const Error& error)
    {
      throw Error(unreadable + "; " + error.what());
    }
    io = itk::ImageIOFactory::CreateImageIO(path.c_str(), reading);
  }
  // ITK's MetaImage factory knows ".mha" and ".mhd" in lower case only; NIfTI's and NRRD's any case.
  if (!io && (endsInAnyCase(path, ".mha") || endsInAnyCase(path, ".mhd")))
    io = itk::MetaImageIO::New();
  if (!io && isNifti2(path))
    throw Error(path + ": a NIfTI-2 file, which SliceMesh does not read; save it as NIfTI-1 (.nii)");
  if (!io)
    throw Error(unreadable);
  try
  {
    io->SetFileName(path);
    io->ReadImageInformation(); // MetaIO's multi-line complaints go nowhere (silenced, above)
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot read the image header: " + itkErrorText(error));
  }
  correctHeaderSpace(io, readerSpaceCorrection(path, nifti));
  // GDCM gives a DICOM file of one frame as a volume of one slice 1 mm thick, a thickness it makes
  // up: a slice of a series given instead of its folder would be meshed as a 1 mm slab.
  if (std::string(io->GetNameOfClass()) == "GDCMImageIO" && io->GetNumberOfDimensions() == 3 && io->GetDimensions(2) == 1)
    throw Error(path + ": a single DICOM slice (a 2-D image); SliceMesh needs a 3-D volume: give the folder of its series");
  return io;
}

/** The header of an image file, checked (an uncompressed NRRD's or MetaImage's size, dimension,
 *  components, geometry, NIfTI's size and spacing, memory; `asStored` as checkHeader's) before any
 *  voxel is read. */
itk::ImageIOBase::Pointer checkedImageHeader(const std::string& path, bool asStored)
{
  if (endsInAnyCase(path, ".gz"))
    checkGzipStream(path);
  checkDetachedDataFile(path);
  itk::ImageIOBase::Pointer io = readImageHeader(path);
  // Before the memory check: a header claiming more voxels than the file holds is a damaged file,
  // whatever memory its voxels would take.
  checkRawVoxelBytes(path, io);
  checkHeader(path, io, asStored);
  // NIfTI-1 (plain or gzip): its header read once, for the two checks.
  const std::optional<Nifti1Header> header = readNifti1Header(path);
  checkNiftiFileSize(path, io, header);
  checkNiftiSpacing(path, header);
  return io;
}

/** The voxels of the image file whose header `io` holds, as TImage's pixels. */
template <typename TImage>
typename TImage::Pointer readImageFileAs(const std::string& path, itk::ImageIOBase* io)
{
  // ITK's reader reads the header again, as ITK has it: the volume is placed as `io` (checked and
  // corrected: readImageHeader) places it. This keeps the first three axes' directions of a 4-D
  // file too, where the reader falls back to the identity direction when it drops a dimension.
  typename TImage::PointType origin;
  origin.Fill(0.0);
  typename TImage::DirectionType direction;
  direction.SetIdentity();
  for (unsigned int axis = 0; axis < std::min(io->GetNumberOfDimensions(), 3u); ++axis)
  {
    origin[axis] = io->GetOrigin(axis);
    const std::vector<double> column = io->GetDirection(axis);
    for (unsigned int row = 0; row < std::min<std::size_t>(column.size(), 3); ++row)
      direction[row][axis] = column[row];
  }
  using Reader = itk::ImageFileReader<TImage>;
  auto reader = Reader::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  std::string complaints;
  try
  {
    CapturedErrorStream captured;
    reader->Update();
    complaints = captured.text();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot read the voxels: " + itkErrorText(error));
  }
  if (!complaints.empty())
    throw Error(path + ": cannot read the voxels (a truncated or damaged file?): " + oneLine(complaints));
  typename TImage::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();

  volume->SetOrigin(origin);
  volume->SetDirection(direction);
  checkVolumeGeometry(path, volume);
  return volume;
}

/** The largest image series in the folder (DicomImageFunctions::readSeries), checked. */
ScalarVolume::Pointer readDicomSeries(const std::string& directory, bool voxels)
{
  // GDCM scans every file of the folder: one damaged file would abort the process there.
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.is_regular_file(error))
      checkDicomFileMeta(entry.path().string());
  ScalarVolume::Pointer volume;
  try
  {
    const SilencedStandardError silenced; // GDCM's trace on the files that are not DICOM
    volume = dicomImageFunctions().readSeries(directory, voxels);
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(directory + ": cannot read the DICOM series: " + itkErrorText(error));
  }
  checkVolumeGeometry(directory, volume);
  return volume;
}

} // namespace

void checkVolumeGeometry(const std::string& path, const itk::ImageBase<3>* volume)
{
  double spacing[3], origin[3];
  std::size_t size[3];
  double direction[3][3];
  for (int i = 0; i < 3; ++i)
  {
    spacing[i] = volume->GetSpacing()[i];
    origin[i] = volume->GetOrigin()[i];
    size[i] = volume->GetLargestPossibleRegion().GetSize()[i];
    for (int j = 0; j < 3; ++j)
      direction[i][j] = volume->GetDirection()[i][j];
  }
  checkGeometry(path, spacing, direction, origin, size);
}

namespace
{

/** Whether `path` is a folder, read as a DICOM series; throws naming it when it does not exist. */
bool isSeriesFolder(const std::string& path)
{
  std::error_code ignored;
  if (!std::filesystem::exists(path, ignored))
    throw Error(path + ": no such file or directory");
  return std::filesystem::is_directory(path, ignored);
}

} // namespace

itk::Vector<double, 3> VolumeGeometry::axis(int k) const
{
  itk::Vector<double, 3> column;
  for (int row = 0; row < 3; ++row)
    column[row] = direction[row][k];
  return column;
}

itk::Vector<double, 3> VolumeGeometry::sliceNormal() const
{
  itk::Vector<double, 3> normal = itk::CrossProduct(axis(0), axis(1));
  normal.Normalize();
  return normal * sliceDirection() < 0.0 ? -normal : normal; // Vector * Vector: the dot product
}

double VolumeGeometry::sliceDistance() const
{
  return spacing[2] * std::abs(sliceNormal() * sliceDirection());
}

VolumeGeometry readVolumeGeometry(const std::string& path)
{
  if (!isSeriesFolder(path))
  {
    itk::ImageIOBase::Pointer io = readImageHeader(path);
    if (io->GetNumberOfDimensions() < 3)
      throw Error(path + ": a 2-D image; its slice direction is unknown");
    VolumeGeometry geometry = checkHeaderGeometry(path, io);
    geometry.frameOfReference = frameOfReferenceIn(io->GetMetaDataDictionary());
    return geometry;
  }
  const ScalarVolume::Pointer volume = readDicomSeries(path, /*voxels=*/false);
  VolumeGeometry geometry;
  geometry.frameOfReference = frameOfReferenceIn(volume->GetMetaDataDictionary());
  for (int i = 0; i < 3; ++i)
  {
    geometry.spacing[i] = volume->GetSpacing()[i];
    geometry.origin[i] = volume->GetOrigin()[i];
    for (int j = 0; j < 3; ++j)
      geometry.direction[i][j] = volume->GetDirection()[i][j];
  }
  return geometry;
}


ScalarVolume::Pointer readVolume(const std::string& path)
{
  if (isSeriesFolder(path))
    return readDicomSeries(path, /*voxels=*/true);
  itk::ImageIOBase::Pointer io = checkedImageHeader(path, false);
  return readImageFileAs<ScalarVolume>(path, io);
}

StoredVolume readStoredVolume(const std::string& path)
{
  if (isSeriesFolder(path))
    return readDicomSeries(path, /*voxels=*/true);
  itk::ImageIOBase::Pointer io = checkedImageHeader(path, true);
  switch (io->GetComponentType()) // the types keptAsStored names; float for the others
  {
    case itk::IOComponentEnum::UCHAR: return readImageFileAs<itk::Image<std::uint8_t, 3>>(path, io);
    case itk::IOComponentEnum::CHAR: return readImageFileAs<itk::Image<std::int8_t, 3>>(path, io);
    case itk::IOComponentEnum::USHORT: return readImageFileAs<itk::Image<std::uint16_t, 3>>(path, io);
    case itk::IOComponentEnum::SHORT: return readImageFileAs<itk::Image<std::int16_t, 3>>(path, io);
    case itk::IOComponentEnum::UINT: return readImageFileAs<itk::Image<std::uint32_t, 3>>(path, io);
    case itk::IOComponentEnum::INT: return readImageFileAs<itk::Image<std::int32_t, 3>>(path, io);
    default: return readImageFileAs<ScalarVolume>(path, io);
  }
}

} // namespace slicemesh

// The headers are read here as text, as far as where their voxels start: ITK's readers keep neither
// the data file's name nor the offset of the voxels.
#include "RawVoxelBytes.h"

#include "Core/Lowercase.h"
#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

namespace fs = std::filesystem;

/** A line of a header and the offset of the byte after its line break. */
struct HeaderLine
{
  std::string text; ///< without its line break ("\n" or "\r\n")
  std::uintmax_t end = 0;
};

/** The lines of the first 64 KiB of a file: a header is a few hundred bytes, and a file that is no
 *  such header is not read whole. A line cut off at the end is left out. */
std::vector<HeaderLine> headerLines(const std::string& path)
{
  constexpr std::size_t longestHeader = 1 << 16;
  std::ifstream in(path, std::ios::binary);
  std::string text(longestHeader, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  std::vector<HeaderLine> lines;
  for (std::size_t start = 0, end = 0; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
  {
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back({ line, end + 1 });
  }
  return lines;
}

std::string trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/** Where the voxels are and how many bytes they have there. */
struct VoxelData
{
  fs::path file;
  std::uintmax_t bytes = 0;
  bool deflated = false; ///< gzip or zlib: the bytes decompress to at most deflateLargestRatio times as many
};

/** The most bytes one byte of a deflate stream (gzip, zlib) decompresses to: its longest match, 258
 *  bytes, coded in 2 bits. A bound that costs nothing where the decompressed size would cost a pass. */
constexpr double deflateLargestRatio = 1032.0;

/** The bytes of `file` from `offset` on; all of them for a negative offset (the header's -1: the
 *  voxels are the file's last bytes). Empty if the file's size cannot be read. */
std::optional<VoxelData> dataFrom(const fs::path& file, long long offset, bool deflated)
{
  std::error_code error;
  const std::uintmax_t size = fs::file_size(file, error);
  if (error)
    return std::nullopt;
  const std::uintmax_t skipped = offset < 0 ? 0 : static_cast<std::uintmax_t>(offset);
  return VoxelData{ file, size > skipped ? size - skipped : 0, deflated };
}

/** A detached header's data file `named`: as named if absolute, else beside the header. */
fs::path dataFileOf(const std::string& header, const std::string& named)
{
  return fs::path(named).is_absolute() ? fs::path(named) : fs::path(header).parent_path() / named;
}

/** A whole number of a header field, or `otherwise` if it holds none. */
long long wholeNumber(const std::string& text, long long otherwise)
{
  std::istringstream in(text);
  long long value = 0;
  return in >> value ? value : otherwise;
}

/** NRRD: "field: value" lines up to the first empty one, the voxels after it or in the file its
 *  "data file" names; "byte skip" bytes skipped first (-1: the voxels end the file). */
std::optional<VoxelData> nrrdVoxelData(const std::string& path)
{
  const std::vector<HeaderLine> lines = headerLines(path);
  if (lines.empty() || lines.front().text.rfind("NRRD", 0) != 0)
    return std::nullopt;
  std::string encoding, dataFile;
  long long byteSkip = 0;
  std::optional<std::uintmax_t> headerEnd;
  for (std::size_t at = 1; at < lines.size(); ++at)
  {
    const std::string& line = lines[at].text;
    if (line.empty())
    {
      headerEnd = lines[at].end;
      break;
    }
    const std::size_t colon = line.find(':');
    if (line[0] == '#' || colon == std::string::npos || line.compare(colon, 2, ":=") == 0)
      continue; // a comment, or a key/value pair
    const std::string field = line.substr(0, colon);
    const std::string value = trimmed(line.substr(colon + 1));
    if (field == "encoding")
      encoding = lowercase(value);
    else if (field == "data file" || field == "datafile")
      dataFile = value;
    else if (field == "byte skip" || field == "byteskip")
      byteSkip = wholeNumber(value, 0);
  }
  const bool deflated = encoding == "gzip" || encoding == "gz";
  if (encoding != "raw" && !deflated)
    return std::nullopt; // text, hex or bzip2

  if (!dataFile.empty())
  {
    // "LIST" or a pattern ("slice%03d.raw 1 40 1"): several files.
    if (dataFile.rfind("LIST", 0) == 0 || dataFile.find(' ') != std::string::npos)
      return std::nullopt;
    return dataFrom(dataFileOf(path, dataFile), byteSkip, deflated);
  }
  if (!headerEnd)
    return std::nullopt;
  return dataFrom(path, byteSkip < 0 ? -1 : static_cast<long long>(*headerEnd) + byteSkip, deflated);
}

/** MetaIO's reading of a true field: its first letter T or t, or 1. */
bool isTrue(const std::string& value)
{
  return !value.empty() && (value[0] == 'T' || value[0] == 't' || value[0] == '1');
}

/** MetaImage: "Key = Value" lines up to ElementDataFile, the voxels after it (LOCAL) or in the file it
 *  names; HeaderSize, where given, is where they start in that file (-1: they end it). */
std::optional<VoxelData> metaImageVoxelData(const std::string& path)
{
  bool binary = false, compressed = false;
  long long headerSize = 0;
  for (const HeaderLine& line : headerLines(path))
  {
    const std::size_t equals = line.text.find('=');
    if (equals == std::string::npos)
      continue;
    const std::string key = trimmed(line.text.substr(0, equals));
    const std::string value = trimmed(line.text.substr(equals + 1));
    if (key == "BinaryData")
      binary = isTrue(value);
    else if (key == "CompressedData")
      compressed = isTrue(value);
    else if (key == "HeaderSize")
      headerSize = wholeNumber(value, 0);
    else if (key == "ElementDataFile")
    {
      if (!binary)
        return std::nullopt; // text
      if (lowercase(value) == "local")
        return dataFrom(path, headerSize != 0 ? headerSize : static_cast<long long>(line.end), compressed);
      // A list or a pattern names several files; a missing file MetaIO looks for as .gz or .Z.
      const fs::path data = dataFileOf(path, value);
      std::error_code error;
      if (value.rfind("LIST", 0) == 0 || value.find('%') != std::string::npos || !fs::is_regular_file(data, error))
        return std::nullopt;
      return dataFrom(data, headerSize, compressed);
    }
  }
  return std::nullopt;
}

} // namespace

void checkRawVoxelBytes(const std::string& path, const itk::ImageIOBase* io)
{
  std::optional<VoxelData> data;
  if (endsInAnyCase(path, ".nrrd") || endsInAnyCase(path, ".nhdr"))
    data = nrrdVoxelData(path);
  else if (endsInAnyCase(path, ".mha") || endsInAnyCase(path, ".mhd"))
    data = metaImageVoxelData(path);
  if (!data)
    return;
  // In double: a damaged header's sizes can multiply past any integer type.
  double claimed = static_cast<double>(io->GetComponentSize()) * io->GetNumberOfComponents();
  for (unsigned int axis = 0; axis < io->GetNumberOfDimensions(); ++axis)
    claimed *= static_cast<double>(io->GetDimensions(axis));
  const double held = static_cast<double>(data->bytes);
  if ((data->deflated ? deflateLargestRatio * held : held) >= claimed)
    return;
  std::ostringstream message;
  message << std::fixed << std::setprecision(0) << path << ": "
          << (data->file == fs::path(path) ? std::string("the file") : "its data file '" + data->file.string() + "'")
          << " holds " << held << " bytes of " << (data->deflated ? "compressed " : "") << "voxel data";
  if (data->deflated)
    message << " (at most " << deflateLargestRatio * held << " decompressed)";
  message << " where its header claims " << claimed << " (a truncated file?)";
  throw Error(message.str());
}

} // namespace slicemesh

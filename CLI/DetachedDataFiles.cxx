#include "DetachedDataFiles.h"

#include "Core/Lowercase.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

namespace slicemesh::cli
{
namespace
{

namespace fs = std::filesystem;

/** Past this much a header is read no further: a NRRD's or MetaImage's is a few hundred bytes, a
 *  LIST of slice files some kilobytes; a file of voxels without line breaks is not read whole. */
constexpr std::size_t mostHeaderBytes = std::size_t(1) << 20;

/** A format string's names past this many are not listed: a series of slices has hundreds. */
constexpr long long mostFormattedNames = 10000;

/** A header read line by line, mostHeaderBytes at most. */
class HeaderLines
{
public:
  explicit HeaderLines(const fs::path& path)
    : m_In(path, std::ios::binary)
  {
  }

  /** The next line without its line break (nor a CR before it); false at the end. */
  bool next(std::string& line)
  {
    line.clear();
    bool any = false;
    for (int c; m_Read < mostHeaderBytes && (c = m_In.get()) != std::char_traits<char>::eof();)
    {
      ++m_Read;
      any = true;
      if (c == '\n')
        break;
      line.push_back(static_cast<char>(c));
    }
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return any;
  }

private:
  std::ifstream m_In;
  std::size_t m_Read = 0;
};

std::string trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> words(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::string> all;
  for (std::string word; in >> word;)
    all.push_back(word);
  return all;
}

/** A whole number of an int's range, as a format string's min, max and step are. */
std::optional<long long> wholeNumber(const std::string& text)
{
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < -2147483648LL || value > 2147483647LL)
    return std::nullopt;
  return value;
}

/** `number` as printf's "%0<width>d" (pad '0') or "%<width>d" (pad ' ') writes it: formatted here,
 *  so that no format from a file reaches printf. */
std::string formatted(long long number, std::size_t width, char pad)
{
  const std::string text = std::to_string(number);
  if (text.size() >= width)
    return text;
  if (pad == '0' && number < 0)
    return "-" + std::string(width - text.size(), '0') + text.substr(1);
  return std::string(width - text.size(), pad) + text;
}

/** The names a format string makes from `first` to `last` by `step` ("slice%03d.raw 1 40 1"); none
 *  for a format of anything but one conversion "%d" (or i, u), zero-padded or with a width, the
 *  forms the formats' own examples use. */
std::vector<std::string> formattedNames(const std::string& format, long long first, long long last, long long step)
{
  std::string before, after;
  std::optional<std::pair<std::size_t, char>> conversion; // width, pad
  for (std::size_t at = 0; at < format.size(); ++at)
  {
    std::string& text = conversion ? after : before;
    if (format[at] != '%')
      text += format[at];
    else if (at + 1 < format.size() && format[at + 1] == '%')
      text += format[++at];
    else
    {
      const char pad = at + 1 < format.size() && format[at + 1] == '0' ? '0' : ' ';
      std::size_t end = at + (pad == '0' ? 2 : 1);
      const std::size_t widthStart = end;
      while (end < format.size() && std::isdigit(static_cast<unsigned char>(format[end])))
        ++end;
      constexpr std::size_t mostWidthDigits = 3;
      if (conversion || end >= format.size() || std::string("diu").find(format[end]) == std::string::npos ||
          end - widthStart > mostWidthDigits)
        return {};
      conversion = { static_cast<std::size_t>(std::atoi(format.substr(widthStart, end - widthStart).c_str())), pad };
      at = end;
    }
  }
  std::vector<std::string> names;
  if (!conversion || step == 0)
    return names;
  for (long long n = first; (step > 0 ? n <= last : n >= last) && static_cast<long long>(names.size()) < mostFormattedNames;
       n += step)
    names.push_back(before + formatted(n, conversion->first, conversion->second) + after);
  return names;
}

/** The files a NRRD `data file:` or a MetaImage ElementDataFile value names, as written: one file,
 *  a format string and its min, max and step (a fifth number, the slices' dimension, aside), or
 *  LIST and the names on the lines after it. */
std::vector<std::string> namedFiles(const std::string& value, HeaderLines& rest)
{
  const std::vector<std::string> parts = words(value);
  if (!parts.empty() && parts[0] == "LIST")
  {
    std::vector<std::string> names;
    for (std::string line; rest.next(line);)
      if (!trimmed(line).empty())
        names.push_back(trimmed(line));
    return names;
  }
  if ((parts.size() == 4 || parts.size() == 5) && parts[0].find('%') != std::string::npos)
  {
    const auto first = wholeNumber(parts[1]), last = wholeNumber(parts[2]), step = wholeNumber(parts[3]);
    if (first && last && step)
      return formattedNames(parts[0], *first, *last, *step);
  }
  return { value };
}

/** A NRRD's `data file:` field (teem also spells it `datafile:`), up to the empty line ending the
 *  header; `key:=value` pairs and comments passed over. */
std::vector<std::string> nrrdDataFiles(HeaderLines& header)
{
  for (std::string line; header.next(line) && !line.empty();)
  {
    const std::size_t colon = line.find(':');
    if (line[0] == '#' || colon == std::string::npos || line.compare(colon, 2, ":=") == 0)
      continue;
    const std::string field = lowercase(trimmed(line.substr(0, colon)));
    if (field == "data file" || field == "datafile")
      return namedFiles(trimmed(line.substr(colon + 1)), header);
  }
  return {};
}

/** A MetaImage's ElementDataFile, its last field: none when LOCAL (the voxels follow it). */
std::vector<std::string> metaImageDataFiles(HeaderLines& header)
{
  for (std::string line; header.next(line);)
  {
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos || lowercase(trimmed(line.substr(0, equals))) != "elementdatafile")
      continue;
    const std::string value = trimmed(line.substr(equals + 1));
    if (lowercase(value) == "local")
      return {};
    return namedFiles(value, header);
  }
  return {};
}

/** The other half of an Analyze or NIfTI pair, .hdr and .img (gzipped alike), or nothing. */
std::optional<std::string> otherHalfOfPair(const std::string& path)
{
  for (const auto& [from, to] : { std::pair<std::string, std::string>{ ".hdr", ".img" }, { ".img", ".hdr" },
                                  { ".hdr.gz", ".img.gz" }, { ".img.gz", ".hdr.gz" } })
    if (endsInAnyCase(path, from))
      return path.substr(0, path.size() - from.size()) + to;
  return std::nullopt;
}

} // namespace

std::vector<std::string> detachedDataFiles(const std::string& volumePath)
{
  std::error_code error;
  if (volumePath.empty() || !fs::is_regular_file(volumePath, error))
    return {};
  if (const std::optional<std::string> pair = otherHalfOfPair(volumePath))
    return { *pair };
  HeaderLines header(volumePath);
  std::string firstLine;
  if (!header.next(firstLine))
    return {};
  std::vector<std::string> names;
  if (firstLine.rfind("NRRD", 0) == 0)
    names = nrrdDataFiles(header);
  else if (endsInAnyCase(volumePath, ".mhd") || endsInAnyCase(volumePath, ".mha"))
  {
    HeaderLines fromTheStart(volumePath); // the first line may be ElementDataFile's own
    names = metaImageDataFiles(fromTheStart);
  }
  // Relative names are found from the header's folder, as the readers find them.
  const fs::path folder = fs::path(volumePath).parent_path();
  for (std::string& name : names)
    if (fs::path(name).is_relative())
      name = (folder / name).string();
  return names;
}

} // namespace slicemesh::cli

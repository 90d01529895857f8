#include "LegacyCellLists.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

std::string lowercase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** An ASCII value as VTK's legacy reader takes it into an int, else empty. */
std::optional<long long> integer(const std::string& word)
{
  std::size_t used = 0;
  try
  {
    const long long value = std::stoll(word, &used);
    if (used == word.size() && value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max())
      return value;
  }
  catch (const std::exception&)
  {
  }
  return std::nullopt;
}

} // namespace

std::optional<std::string> legacyCellListFault(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string versionLine, title, format;
  if (!std::getline(in, versionLine) || !std::getline(in, title) || !std::getline(in, format))
    return std::nullopt; // VTK reports a file without a header itself
  // VTK takes a version it cannot parse as 0: the legacy cell lists.
  const std::size_t at = lowercase(versionLine).find("version");
  int major = 0;
  if (at != std::string::npos && !(std::istringstream(versionLine.substr(at + 7)) >> major))
    major = 0;
  if (major >= 5)
    return std::nullopt;
  const bool binary = lowercase(format).rfind("binary", 0) == 0;

  for (std::string line; std::getline(in, line);)
  {
    std::istringstream words(line);
    std::string keyword;
    long long cells = 0, size = 0;
    words >> keyword;
    keyword = lowercase(keyword);
    if (keyword != "vertices" && keyword != "lines" && keyword != "polygons" && keyword != "triangle_strips")
      continue;
    const std::string list = "the " + keyword + " list";
    // The header's two numbers, as VTK reads them: the next two words, on this line or the next ones.
    std::string cellsWord, sizeWord;
    if (!(words >> cellsWord))
      in >> cellsWord;
    if (!(words >> sizeWord))
      in >> sizeWord;
    std::string rest;
    std::getline(words, rest);
    // Two whole numbers and nothing after them: VTK takes the digits of "12@" and then reads past the list.
    const std::optional<long long> declaredCells = integer(cellsWord), declaredSize = integer(sizeWord);
    if (!declaredCells || !declaredSize || rest.find_first_not_of(" \t\r") != std::string::npos)
      return list + " does not begin with two whole numbers";
    cells = *declaredCells;
    size = *declaredSize;
    if (size < 0 || cells < 0)
      return list + " declares a negative size";
    // The values, read one by one: a declared size larger than the file costs no memory.
    std::vector<long long> values;
    for (long long n = 0; n < size; ++n)
    {
      std::optional<long long> value;
      if (binary)
      {
        unsigned char bytes[4];
        if (in.read(reinterpret_cast<char*>(bytes), 4))
          value = static_cast<std::int32_t>(static_cast<std::uint32_t>(bytes[0]) << 24 | static_cast<std::uint32_t>(bytes[1]) << 16 |
                                            static_cast<std::uint32_t>(bytes[2]) << 8 | bytes[3]); // big-endian
      }
      else if (std::string word; in >> word)
        value = integer(word);
      if (!value)
        return list + " declares " + std::to_string(size) + " values but holds " + std::to_string(n);
      values.push_back(*value);
    }
    // Each cell: its point count, then that many point ids, all inside the list.
    for (std::size_t n = 0; n < values.size();)
    {
      const long long points = values[n];
      if (points < 0 || static_cast<long long>(values.size() - n - 1) < points)
        return list + " has a cell of " + std::to_string(points) + " points where " +
               std::to_string(values.size() - n - 1) + " values are left";
      n += static_cast<std::size_t>(points) + 1;
    }
    if (!binary)
      std::getline(in, line); // the rest of the last line of values
  }
  return std::nullopt;
}

} // namespace slicemesh

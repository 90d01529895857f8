#include "LegacyPolyDataReader.h"
#include "Core/Lowercase.h"

#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace slicemesh
{
namespace
{

/** A word of the file as it may be quoted in a one-line error: printable and short. */
std::string quotable(const std::string& word)
{
  std::string shown;
  for (const char c : word.substr(0, 40))
    shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return shown;
}

/** How a value type of the format is stored in a binary file (big-endian). */
struct ValueType
{
  std::size_t bytes = 0;
  bool isFloat = false;
  bool isSigned = false;
};

std::optional<ValueType> valueType(const std::string& name)
{
  static const std::map<std::string, ValueType> types = {
    { "unsigned_char", { 1, false, false } },  { "char", { 1, false, true } },
    { "unsigned_short", { 2, false, false } }, { "short", { 2, false, true } },
    { "unsigned_int", { 4, false, false } },   { "int", { 4, false, true } },
    { "unsigned_long", { 8, false, false } },  { "long", { 8, false, true } },
    { "vtktypeuint64", { 8, false, false } },  { "vtktypeint64", { 8, false, true } },
    { "vtkidtype", { 4, false, true } },       { "float", { 4, true, true } },
    { "double", { 8, true, true } },
  };
  const auto found = types.find(lowercase(name));
  return found == types.end() ? std::nullopt : std::optional<ValueType>(found->second);
}

/** The file's bytes and a read position; every read checks the end. */
class Cursor
{
public:
  Cursor(std::string bytes, std::string path)
    : m_Bytes(std::move(bytes))
    , m_Path(std::move(path))
  {
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Error("cannot read '" + m_Path + "' as VTK polydata: " + what);
  }

  bool atEnd()
  {
    skipSpace();
    return m_At >= m_Bytes.size();
  }

  std::string line(const std::string& what)
  {
    if (m_At >= m_Bytes.size())
      fail("the file ends before " + what);
    const std::size_t end = std::min(m_Bytes.find('\n', m_At), m_Bytes.size());
    std::string text = m_Bytes.substr(m_At, end - m_At);
    m_At = end + 1;
    if (!text.empty() && text.back() == '\r')
      text.pop_back();
    return text;
  }

  /** The next whitespace-separated word, on this line or a later one. */
  std::string word(const std::string& what)
  {
    skipSpace();
    const std::size_t start = m_At;
    while (m_At < m_Bytes.size() && !std::isspace(static_cast<unsigned char>(m_Bytes[m_At])))
      ++m_At;
    if (start == m_At)
      fail("the file ends before " + what);
    return m_Bytes.substr(start, m_At - start);
  }

  /** A count of a section's header: a whole number from 0 to 2^31. */
  std::int64_t count(const std::string& what)
  {
    const std::string text = word(what);
    const std::optional<std::int64_t> value = wholeNumber(text);
    if (!value || *value < 0 || *value > std::numeric_limits<std::int32_t>::max())
      fail(what + " is '" + quotable(text) + "', not a count");
    return *value;
  }

  /** The rest of the current line: binary values start on the next one. */
  void skipLine()
  {
    const std::size_t end = m_Bytes.find('\n', m_At);
    m_At = end == std::string::npos ? m_Bytes.size() : end + 1;
  }

  /** Lines up to and including the next empty one (a METADATA block). */
  void skipBlock()
  {
    skipLine();
    while (m_At < m_Bytes.size())
    {
      const std::string text = line("the end of a METADATA block");
      if (text.find_first_not_of(" \t\r") == std::string::npos)
        return;
    }
  }

  /** count values of the type, ASCII or binary, as doubles. */
  std::vector<double> values(std::int64_t count, const ValueType& type, bool binary, const std::string& what)
  {
    auto fromWord = [](const std::string& text) -> std::optional<double>
    {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      return end == text.c_str() + text.size() ? std::optional<double>(value) : std::nullopt;
    };
    return valuesOf<double>(count, type, binary, what, "a number", fromWord, [&] { return binaryValue(type); });
  }

  /** count whole numbers of an integer type (point ids, offsets), ASCII or binary. */
  std::vector<std::int64_t> integers(std::int64_t count, const ValueType& type, bool binary, const std::string& what)
  {
    auto fromBytes = [&]
    {
      const std::uint64_t raw = bigEndian(type.bytes);
      if (!type.isSigned && raw > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        fail(what + " holds an id beyond any file's size");
      const unsigned shift = static_cast<unsigned>(64 - 8 * type.bytes); // sign-extend
      return type.isSigned ? static_cast<std::int64_t>(raw << shift) >> shift : static_cast<std::int64_t>(raw);
    };
    return valuesOf<std::int64_t>(count, type, binary, what, "a whole number", wholeNumber, fromBytes);
  }

  /** count strings of an array: one per line, %XX-escaped, in ASCII; length-prefixed in binary. */
  std::vector<std::string> strings(std::int64_t count, bool binary, const std::string& what)
  {
    std::vector<std::string> read;
    skipLine();
    for (std::int64_t n = 0; n < count; ++n)
      read.push_back(binary ? binaryString(what) : unescaped(line(what + "'s strings")));
    return read;
  }

private:
  void skipSpace()
  {
    while (m_At < m_Bytes.size() && std::isspace(static_cast<unsigned char>(m_Bytes[m_At])))
      ++m_At;
  }

  /** count values: in ASCII the next words, each parsed by fromWord (empty: not a value of this kind);
   *  in binary, from the next line on, each converted by fromBytes at the read position. */
  template <typename T, typename FromWord, typename FromBytes>
  std::vector<T> valuesOf(std::int64_t count, const ValueType& type, bool binary, const std::string& what,
                          const char* kind, FromWord fromWord, FromBytes fromBytes)
  {
    std::vector<T> read;
    if (binary)
    {
      skipLine();
      checkBinaryRoom(count, type, what);
      read.reserve(static_cast<std::size_t>(count));
      for (std::int64_t n = 0; n < count; ++n, m_At += type.bytes)
        read.push_back(fromBytes());
      return read;
    }
    for (std::int64_t n = 0; n < count; ++n)
    {
      skipSpace();
      if (m_At >= m_Bytes.size())
        fail(what + " declares " + std::to_string(count) + " values but holds " + std::to_string(n));
      const std::string text = word(what);
      const std::optional<T> value = fromWord(text);
      if (!value)
        fail(what + " holds '" + quotable(text) + "', not " + kind);
      read.push_back(*value);
    }
    return read;
  }

  void checkBinaryRoom(std::int64_t count, const ValueType& type, const std::string& what) const
  {
    const std::size_t left = m_Bytes.size() - std::min(m_At, m_Bytes.size());
    if (static_cast<std::uint64_t>(count) > left / type.bytes)
      fail(what + " declares " + std::to_string(count) + " values, more than the file holds");
  }

  static std::optional<std::int64_t> wholeNumber(const std::string& text)
  {
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
      return std::nullopt;
    return value;
  }

  std::uint64_t bigEndian(std::size_t bytes) const
  {
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < bytes; ++i)
      value = value << 8 | static_cast<unsigned char>(m_Bytes[m_At + i]);
    return value;
  }

  double binaryValue(const ValueType& type) const
  {
    const std::uint64_t raw = bigEndian(type.bytes);
    if (type.isFloat && type.bytes == 4)
    {
      const auto bits = static_cast<std::uint32_t>(raw);
      float value;
      std::memcpy(&value, &bits, 4);
      return value;
    }
    if (type.isFloat)
    {
      double value;
      std::memcpy(&value, &raw, 8);
      return value;
    }
    if (!type.isSigned)
      return static_cast<double>(raw);
    const unsigned shift = static_cast<unsigned>(64 - 8 * type.bytes); // sign-extend
    return static_cast<double>(static_cast<std::int64_t>(raw << shift) >> shift);
  }

  /** A binary string: its length in 1, 2, 4 or 8 bytes, the first two bits saying which. */
  std::string binaryString(const std::string& what)
  {
    if (m_At >= m_Bytes.size())
      fail(what + " ends before its strings");
    const auto first = static_cast<unsigned char>(m_Bytes[m_At]);
    const std::size_t headerBytes = first >> 6 == 3 ? 1 : first >> 6 == 2 ? 2 : first >> 6 == 1 ? 4 : 8;
    if (m_Bytes.size() - m_At < headerBytes)
      fail(what + " ends inside a string's length");
    const std::uint64_t length = bigEndian(headerBytes) & ((std::uint64_t{ 1 } << (8 * headerBytes - 2)) - 1);
    m_At += headerBytes;
    if (length > m_Bytes.size() - m_At)
      fail(what + " declares a string longer than the file");
    std::string text = m_Bytes.substr(m_At, static_cast<std::size_t>(length));
    m_At += static_cast<std::size_t>(length);
    return text;
  }

  /** The format writes spaces and other unprintable characters of a string as %XX. */
  static std::string unescaped(const std::string& text)
  {
    std::string plain;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
      if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
          std::isxdigit(static_cast<unsigned char>(text[i + 2])))
      {
        plain += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
        i += 2;
      }
      else
        plain += text[i];
    }
    return plain;
  }

  std::string m_Bytes;
  std::string m_Path;
  std::size_t m_At = 0;
};

/** A cell list of format 4: per cell its point count, then the ids, size values in all. */
std::vector<std::vector<std::int64_t>> cellList(Cursor& in, bool binary, const std::string& what)
{
  const std::int64_t cells = in.count("the cell count of " + what);
  const std::int64_t size = in.count("the size of " + what);
  const std::vector<std::int64_t> values = in.integers(size, ValueType{ 4, false, true }, binary, what);
  std::vector<std::vector<std::int64_t>> list;
  for (std::size_t n = 0; n < values.size();)
  {
    const std::int64_t points = values[n];
    const auto left = static_cast<std::int64_t>(values.size() - n - 1);
    if (points < 0 || points > left)
      in.fail(what + " has a cell of " + std::to_string(points) + " points where " + std::to_string(left) +
              " values are left");
    list.emplace_back(values.begin() + static_cast<std::ptrdiff_t>(n + 1),
                      values.begin() + static_cast<std::ptrdiff_t>(n + 1 + static_cast<std::size_t>(points)));
    n += static_cast<std::size_t>(points) + 1;
  }
  if (static_cast<std::int64_t>(list.size()) != cells)
    in.fail(what + " declares " + std::to_string(cells) + " cells but holds " + std::to_string(list.size()));
  return list;
}

/** One array of a format-5 cell list: its keyword, its type, then count values. */
std::vector<std::int64_t> cellArray(Cursor& in, const std::string& keyword, std::int64_t count, bool binary, const std::string& what)
{
  const std::string found = in.word(what + "'s " + keyword);
  if (lowercase(found) != lowercase(keyword))
    in.fail(what + " has '" + quotable(found) + "' where " + keyword + " belongs");
  const std::string typeName = in.word(what + "'s " + keyword + " type");
  const std::optional<ValueType> type = valueType(typeName);
  if (!type || type->isFloat)
    in.fail(what + "'s " + keyword + " are of type '" + quotable(typeName) + "', not whole numbers");
  return in.integers(count, *type, binary, what + "'s " + keyword);
}

/** A cell list of format 5: offsets into a connectivity array. */
std::vector<std::vector<std::int64_t>> offsetCellList(Cursor& in, bool binary, const std::string& what)
{
  const std::int64_t offsetCount = in.count("the offset count of " + what);
  const std::int64_t connectivityCount = in.count("the size of " + what);
  const std::vector<std::int64_t> offsets = cellArray(in, "OFFSETS", offsetCount, binary, what);
  const std::vector<std::int64_t> connectivity = cellArray(in, "CONNECTIVITY", connectivityCount, binary, what);
  std::vector<std::vector<std::int64_t>> list;
  for (std::size_t n = 0; n + 1 < offsets.size(); ++n)
  {
    if (offsets[n] < 0 || offsets[n] > offsets[n + 1] || offsets[n + 1] > static_cast<std::int64_t>(connectivity.size()))
      in.fail(what + " has offsets that do not rise within its " + std::to_string(connectivity.size()) + " ids");
    list.emplace_back(connectivity.begin() + static_cast<std::ptrdiff_t>(offsets[n]),
                      connectivity.begin() + static_cast<std::ptrdiff_t>(offsets[n + 1]));
  }
  return list;
}

/** A FIELD block: its arrays, of which the string ones are kept (first value each). */
void fieldData(Cursor& in, bool binary, std::map<std::string, std::string>& strings)
{
  in.word("the field's name");
  const std::int64_t arrays = in.count("the field's number of arrays");
  for (std::int64_t a = 0; a < arrays; ++a)
  {
    const std::string name = in.word("a field array's name");
    if (name == "NULL_ARRAY")
      continue;
    const std::int64_t components = in.count("the components of field array '" + quotable(name) + "'");
    const std::int64_t tuples = in.count("the tuples of field array '" + quotable(name) + "'");
    const std::string typeName = in.word("the type of field array '" + quotable(name) + "'");
    const std::string what = "field array '" + quotable(name) + "'";
    if (lowercase(typeName) == "string" || lowercase(typeName) == "utf8_string")
    {
      const std::vector<std::string> values = in.strings(components * tuples, binary, what);
      if (!values.empty())
        strings.emplace(name, values.front());
      continue;
    }
    const std::optional<ValueType> type = valueType(typeName);
    if (!type)
      in.fail(what + " is of type '" + quotable(typeName) + "', which a contour file does not hold");
    in.values(components * tuples, *type, binary, what);
  }
}

} // namespace

PolyDataGeometry readLegacyPolyData(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw Error("cannot read '" + path + "': cannot open it");
  Cursor in(std::string(std::istreambuf_iterator<char>(file), {}), path);

  const std::string version = in.line("its first line");
  if (lowercase(version).rfind("# vtk datafile version", 0) != 0)
    in.fail("it does not begin with '# vtk DataFile Version'");
  // Format 5 stores cells as offsets and connectivity; a version that cannot be read is an old one.
  int major = 0;
  if (!(std::istringstream(version.substr(std::strlen("# vtk DataFile Version"))) >> major))
    major = 0;
  PolyDataGeometry data;
  data.title = in.line("its title line");
  const std::string encoding = lowercase(in.word("ASCII or BINARY"));
  if (encoding != "ascii" && encoding != "binary")
    in.fail("the third line is '" + quotable(encoding) + "', not ASCII or BINARY");
  const bool binary = encoding == "binary";
  if (lowercase(in.word("DATASET")) != "dataset")
    in.fail("no DATASET after the header");
  const std::string dataset = in.word("the dataset's type");
  if (lowercase(dataset) != "polydata")
    in.fail("it holds a " + quotable(dataset) + ", not POLYDATA");

  auto cells = [&](const std::string& what)
  { return major >= 5 ? offsetCellList(in, binary, what) : cellList(in, binary, what); };
  while (!in.atEnd())
  {
    const std::string keyword = in.word("a section");
    const std::string section = lowercase(keyword);
    if (section == "point_data" || section == "cell_data")
      break; // per point and per cell values: not part of a contour
    if (section == "field")
      fieldData(in, binary, data.fieldStrings);
    else if (section == "metadata")
      in.skipBlock();
    else if (section == "points")
    {
      const std::int64_t count = in.count("the number of points");
      const std::string typeName = in.word("the points' type");
      const std::optional<ValueType> type = valueType(typeName);
      if (!type)
        in.fail("the points are of type '" + quotable(typeName) + "', not a number type");
      const std::vector<double> xyz = in.values(3 * count, *type, binary, "the points list");
      data.points.resize(static_cast<std::size_t>(count));
      for (std::size_t i = 0; i < data.points.size(); ++i)
        data.points[i] = { xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] };
    }
    else if (section == "lines")
      data.lines = cells("the lines list");
    else if (section == "polygons")
      data.polygons = cells("the polygons list");
    else if (section == "vertices" || section == "triangle_strips")
      cells("the " + section + " list");
    else
      in.fail("unknown section '" + quotable(keyword) + "'");
  }
  return data;
}

} // namespace slicemesh

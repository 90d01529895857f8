// Colour table parsing (Slicer, FreeSurfer, ITK-SNAP, plain name lists) and generated colours.
#include "ColorTable.h"

#include "Core/SliceMeshTypes.h"
#include "Core/Utf8.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

/** A line of an ITK-SNAP label description file, `IDX R G B A VIS MSH "name"`: the name is the
 *  quoted text (spaces and '#' in it kept), the numbers before it the value and colour, the opacity
 *  A from 0 to 1 (VIS and MSH, the label's visibility, are not the mesh's). False for a line without
 *  a quoted name. Throws `malformed` for a quoted line whose numbers are not a value and a colour. */
bool readQuotedLine(const std::string& line, LabelColor& entry, const std::string& malformed)
{
  const std::size_t open = line.find('"');
  if (open == std::string::npos || line.find('#') < open)
    return false;
  const std::size_t close = line.find('"', open + 1);
  if (close == std::string::npos)
    throw Error(malformed);
  std::istringstream fields(line.substr(0, open));
  std::vector<double> numbers;
  for (std::string word; fields >> word;)
  {
    char* end = nullptr;
    numbers.push_back(std::strtod(word.c_str(), &end));
    if (*end != '\0')
      throw Error(malformed);
  }
  if (numbers.empty() || numbers[0] != std::floor(numbers[0]) || !(std::abs(numbers[0]) < 2147483648.0))
    throw Error(malformed);
  entry.label = static_cast<int>(numbers[0]);
  entry.name = line.substr(open + 1, close - open - 1);
  if (entry.name.empty())
    entry.name = "Label_" + std::to_string(entry.label);
  entry.rgba = ColorTable::generatedColor(entry.label);
  if (numbers.size() >= 4)
    for (int c = 0; c < 3; ++c)
    {
      if (!(numbers[c + 1] >= 0.0 && numbers[c + 1] <= 255.0))
        throw Error(malformed);
      entry.rgba[c] = static_cast<unsigned char>(std::lround(numbers[c + 1]));
    }
  if (numbers.size() >= 5)
  {
    if (!(numbers[4] >= 0.0 && numbers[4] <= 1.0))
      throw Error(malformed);
    entry.rgba[3] = static_cast<unsigned char>(std::lround(255.0 * numbers[4]));
  }
  return true;
}

} // namespace

ColorTable ColorTable::read(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw Error(path + ": cannot open the colour table");
  ColorTable table;
  std::string line;
  std::size_t lineNumber = 0;
  bool everyAlphaZero = true;
  bool anyAlpha = false;
  auto add = [&table](const LabelColor& entry) // a value listed again takes its last line
  {
    if (table.Entries.count(entry.label))
      table.Repeated.push_back(entry.label);
    table.Entries[entry.label] = entry;
  };
  while (std::getline(in, line))
  {
    ++lineNumber;
    const std::string malformed = path + ":" + std::to_string(lineNumber) + ": expected 'value name [r g b [a]]'";
    if (LabelColor quoted; readQuotedLine(line, quoted, malformed))
    {
      add(quoted);
      continue;
    }
    if (const std::size_t hash = line.find('#'); hash != std::string::npos)
      line.erase(hash);
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string word; fields >> word;)
      words.push_back(word);
    if (words.empty())
      continue;
    LabelColor entry;
    char* end = nullptr;
    const long value = std::strtol(words[0].c_str(), &end, 10);
    if (*end != '\0' || words.size() < 2)
      throw Error(malformed);
    entry.label = static_cast<int>(value);
    entry.name = words[1];
    entry.rgba = generatedColor(entry.label);
    // "value name r g b [a]"; a single number after the name (MRIcron's group code) is no colour.
    if (words.size() >= 5)
    {
      for (int c = 0; c < 4 && c + 2 < static_cast<int>(words.size()); ++c)
      {
        // Slicer writes a colour node's table as each component times 255, so a colour or opacity
        // that is no multiple of 1/255 (an opacity of 0.5) arrives as 127.5: rounded, not refused.
        const double component = std::strtod(words[c + 2].c_str(), &end);
        if (*end != '\0' || !(component >= -0.5 && component < 255.5))
          throw Error(path + ":" + std::to_string(lineNumber) + ": colour components must be numbers 0..255");
        entry.rgba[c] = static_cast<unsigned char>(std::lround(std::clamp(component, 0.0, 255.0)));
      }
      if (words.size() >= 6)
      {
        anyAlpha = true;
        everyAlphaZero &= entry.rgba[3] == 0 || entry.label == 0;
      }
      else
        entry.rgba[3] = 255;
    }
    add(entry);
  }
  if (anyAlpha && everyAlphaZero)
    for (auto& entry : table.Entries)
      entry.second.rgba[3] = 255;
  if (table.Entries.empty())
    throw Error(path + ": the colour table lists no label");
  return table;
}

LabelColor ColorTable::entry(int label) const
{
  const auto found = this->Entries.find(label);
  if (found != this->Entries.end())
    return found->second;
  LabelColor entry;
  entry.label = label;
  entry.name = "Label_" + std::to_string(label);
  entry.rgba = generatedColor(label);
  return entry;
}

std::array<unsigned char, 4> ColorTable::generatedColor(int label)
{
  // Hue steps of the golden ratio conjugate spread consecutive labels around the colour wheel.
  const double hue = std::fmod(0.1 + 0.618033988749895 * label, 1.0) * 6.0;
  const double saturation = 0.55, value = 0.9;
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
  double r = 0, g = 0, b = 0;
  switch (sector)
  {
    case 0: r = value, g = t, b = p; break;
    case 1: r = q, g = value, b = p; break;
    case 2: r = p, g = value, b = t; break;
    case 3: r = p, g = q, b = value; break;
    case 4: r = t, g = p, b = value; break;
    default: r = value, g = p, b = q; break;
  }
  return { static_cast<unsigned char>(std::lround(r * 255)), static_cast<unsigned char>(std::lround(g * 255)),
           static_cast<unsigned char>(std::lround(b * 255)), 255 };
}

namespace
{

/** Characters beyond ASCII that show nothing or break a name: controls, spaces, line and paragraph
 *  separators and formatting characters (Unicode's Cc, Zs, Zl, Zp and Cf, with the Hangul fillers that
 *  show as blanks), and the general punctuation block and the specials (the replacement character
 *  among them). Direction marks and overrides reorder how a name reads in a listing. */
constexpr char32_t hiddenRanges[][2] = {
  { 0x80, 0xA0 },       { 0xAD, 0xAD },       { 0x0600, 0x0605 },   { 0x061C, 0x061C },   { 0x06DD, 0x06DD },
  { 0x070F, 0x070F },   { 0x0890, 0x0891 },   { 0x08E2, 0x08E2 },   { 0x115F, 0x1160 },   { 0x1680, 0x1680 },
  { 0x180E, 0x180E },   { 0x2000, 0x206F },   { 0x3000, 0x3000 },   { 0x3164, 0x3164 },   { 0xFEFF, 0xFEFF },
  { 0xFFA0, 0xFFA0 },   { 0xFFF0, 0xFFFF },   { 0x110BD, 0x110BD }, { 0x110CD, 0x110CD }, { 0x13430, 0x1343F },
  { 0x1BCA0, 0x1BCA3 }, { 0x1D173, 0x1D17A }, { 0xE0000, 0xE007F },
};

/** Whether a character beyond ASCII may stand in a file name as it is: the letters and signs of any
 *  script ("Rückenmark", "肝臓"), but none of hiddenRanges. */
bool keptInFileName(char32_t c)
{
  for (const auto& range : hiddenRanges)
    if (c >= range[0] && c <= range[1])
      return false;
  return true;
}

} // namespace

std::string safeFileName(const std::string& name)
{
  std::string safe;
  forEachCharacter(name,
                   [&](const Utf8Character& c)
                   {
                     // One '_' for each character that is not kept (a stray byte is one character).
                     const auto ascii = static_cast<unsigned char>(c.codePoint);
                     const bool kept = c.wellFormed && (c.length == 1 ? std::isalnum(ascii) || ascii == '-' ||
                                                                          ascii == '_' || ascii == '.'
                                                                      : keptInFileName(c.codePoint));
                     // A file name holds at most 255 bytes: a longer segment or label name (a sentence
                     // pasted into Slicer's name field) made the whole run fail to write its file, after
                     // the others were written. Cut between characters, never inside one.
                     if (safe.size() + (kept ? c.length : 1) > maxSafeFileNameLength)
                       return false;
                     if (kept)
                       safe.append(c.bytes, c.length);
                     else
                       safe += '_';
                     return true;
                   });
  return safe.empty() ? std::string("unnamed") : safe;
}

} // namespace slicemesh

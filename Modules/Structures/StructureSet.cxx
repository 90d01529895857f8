// What kind of contour file a path holds, reading by kind, and choosing ROIs.
#include "StructureSet.h"
#include "Core/Lowercase.h"
#include "RTStructureSetPlugin.h"

#include "Core/Utf8.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace slicemesh
{
namespace
{

std::string fileStart(const std::string& path, std::size_t bytes)
{
  std::ifstream in(path, std::ios::binary);
  std::string start(bytes, '\0');
  in.read(start.data(), static_cast<std::streamsize>(bytes));
  start.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
  return start;
}

/** Whether the bytes start as a DICOM dataset stored without the 128-byte preamble and "DICM", as
 *  older systems write one (and DCMTK reads it): its first element, little endian, is of group 0002
 *  (the meta header) or 0008 (the identifying attributes every dataset starts with), in explicit VR
 *  (two capital letters) or implicit (a 32-bit length; under 64 KiB for a first element). No volume
 *  or contour format read here starts so: NIfTI with 348 or 540, the others with text. */
bool startsAsDicomDataset(const std::string& start)
{
  if (start.size() < 8 || start[1] != '\0' || (start[0] != '\x02' && start[0] != '\x08'))
    return false;
  const auto capital = [](char c) { return c >= 'A' && c <= 'Z'; };
  return (capital(start[4]) && capital(start[5])) || (start[6] == '\0' && start[7] == '\0');
}

} // namespace

std::optional<ContourFileKind> detectContourFileKind(const std::string& path)
{
  // A DICOM file's Modality and SOP Class come long before its contours; searching the raw start
  // also recognises a structure set cut short, whose reader then says what is wrong.
  const std::string start = fileStart(path, 65536);
  if ((start.size() >= 132 && start.compare(128, 4, "DICM") == 0) || startsAsDicomDataset(start))
  {
    const bool rtStruct = start.find("RTSTRUCT") != std::string::npos ||
                          start.find("1.2.840.10008.5.1.4.1.1.481.3") != std::string::npos;
    return rtStruct ? std::optional(ContourFileKind::RTStruct) : std::nullopt;
  }
  if (start.rfind("# vtk DataFile", 0) == 0)
    return start.find("POLYDATA") != std::string::npos ? std::optional(ContourFileKind::PolyData) : std::nullopt;
  const std::string head = lowercase(start.substr(0, 1024));
  if ((head.rfind("<?xml", 0) == 0 || head.rfind("<vtkfile", 0) == 0) && head.find("type=\"polydata\"") != std::string::npos)
    return ContourFileKind::PolyData;
  // Windows editors start a UTF-8 text with a byte order mark, which the JSON parser skips.
  const std::size_t text = start.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  const auto first = std::find_if(start.begin() + text, start.end(), [](unsigned char c) { return !std::isspace(c); });
  if (first != start.end() && *first == '{')
    return ContourFileKind::Json;
  return std::nullopt;
}

StructureSet readRTStructureSet(const std::string& path)
{
  return rtStructureSetFunctions().read(path);
}

namespace
{

/** The text with each control character (a line break, a tab, a C1 control) and each line or
 *  paragraph separator as a space: an ROI's name stands on one line in every message and in the
 *  report, and so does each note that names it. */
std::string oneLine(const std::string& text)
{
  std::string line;
  forEachCharacter(text,
                   [&](const Utf8Character& c)
                   {
                     const char32_t code = c.codePoint;
                     const bool control = c.wellFormed && (code < 0x20 || (code >= 0x7F && code < 0xA0) ||
                                                           code == 0x2028 || code == 0x2029);
                     if (control)
                       line += ' ';
                     else
                       line.append(c.bytes, c.length);
                     return true;
                   });
  return line;
}

StructureSet readOfKind(const std::string& path, ContourFileKind kind)
{
  if (kind == ContourFileKind::Automatic)
  {
    const auto detected = detectContourFileKind(path);
    if (!detected)
      throw Error("'" + path + "' is not a contour file (a DICOM RT Structure Set, VTK polydata or SliceMesh JSON)");
    kind = *detected;
  }
  switch (kind)
  {
    case ContourFileKind::RTStruct: return readRTStructureSet(path);
    case ContourFileKind::PolyData: return readContourPolyData(path);
    case ContourFileKind::Json: break;
    case ContourFileKind::Automatic: break;
  }
  return readContourJson(path);
}

} // namespace

StructureSet readStructureSet(const std::string& path, ContourFileKind kind)
{
  StructureSet set = readOfKind(path, kind);
  for (PlanarStructure& structure : set.structures)
  {
    structure.name = oneLine(structure.name);
    structure.unusableBecause = oneLine(structure.unusableBecause);
    for (std::string& note : structure.notes)
      note = oneLine(note);
  }
  for (std::string& note : set.notes)
    note = oneLine(note);
  return set;
}

std::vector<int> markSharedRoiNumbers(StructureSet& set, const std::string& path, const std::string& consequence,
                                      const std::string& reason)
{
  std::map<int, std::vector<std::size_t>> byNumber;
  for (std::size_t n = 0; n < set.structures.size(); ++n)
    byNumber[set.structures[n].number].push_back(n);
  std::vector<int> shared;
  auto quoted = [&](std::size_t n) { return "'" + set.structures[n].name + "'"; };
  for (const auto& [number, rois] : byNumber)
  {
    if (rois.size() < 2)
      continue;
    shared.push_back(number);
    std::string names;
    for (std::size_t k = 0; k < rois.size(); ++k)
      names += (k == 0 ? "" : k + 1 == rois.size() ? " and " : ", ") + quoted(rois[k]);
    set.notes.push_back("'" + path + "': ROI number " + std::to_string(number) + " is given to " +
                        std::to_string(rois.size()) + " ROIs, " + names + ": " + consequence);
    for (const std::size_t n : rois)
    {
      std::string others;
      for (const std::size_t other : rois)
        if (other != n)
          others += (others.empty() ? "" : ", ") + quoted(other);
      set.structures[n].contours.clear();
      set.structures[n].unusableBecause = "ROI number " + std::to_string(number) + " is also given to " + others + ": " + reason;
    }
  }
  return shared;
}

std::vector<PlanarStructure> chosenStructures(const StructureSet& set, const std::vector<std::string>& wanted)
{
  if (wanted.empty())
    return set.structures;
  std::vector<bool> chosen(set.structures.size(), false);
  std::vector<std::string> unmatched;
  for (const std::string& item : wanted)
  {
    // A number is an ROI number first (as --labels takes a label value): an ROI named "3" beside
    // ROI 3 is picked by its name only where no ROI has that number.
    bool matched = false;
    for (std::size_t n = 0; n < set.structures.size(); ++n)
      if (item == std::to_string(set.structures[n].number))
        chosen[n] = matched = true;
    if (!matched)
      for (std::size_t n = 0; n < set.structures.size(); ++n)
        if (item == set.structures[n].name || lowercase(item) == lowercase(set.structures[n].name))
          chosen[n] = matched = true;
    if (!matched)
      unmatched.push_back(item);
  }
  if (!unmatched.empty())
  {
    std::string message = "no ROI is called or numbered";
    for (const std::string& item : unmatched)
      message += " '" + item + "'";
    message += "; the ROIs are";
    bool comma = false;
    for (const PlanarStructure& s : set.structures)
    {
      message += " " + std::to_string(s.number) + " (" + s.name + ")";
      comma = comma || s.name.find(',') != std::string::npos;
    }
    if (comma) // the list is split at commas, as 3D Slicer passes a string vector
      message += "; a name with a comma is picked by its number";
    throw Error(message);
  }
  std::vector<PlanarStructure> result;
  for (std::size_t n = 0; n < set.structures.size(); ++n)
    if (chosen[n])
      result.push_back(set.structures[n]);
  return result;
}

} // namespace slicemesh

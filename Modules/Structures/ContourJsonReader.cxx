// SliceMesh's JSON contour format (Documentation/ContourFiles.md): ROIs -> slices -> polygons, mm.
#include "StructureSet.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace slicemesh
{
namespace
{

using Json = nlohmann::json;

/** The parser's message without its "[json.exception.parse_error.101] " tag. */
std::string messageOf(const Json::exception& e)
{
  const std::string what = e.what();
  const std::size_t tag = what.rfind("] ", what.find(' '));
  return what.compare(0, 16, "[json.exception.") == 0 && tag != std::string::npos ? what.substr(tag + 2) : what;
}

[[noreturn]] void malformed(const std::string& path, const std::string& where, const std::string& what)
{
  throw Error("'" + path + "': " + where + ": " + what);
}

/** A fault in one ROI's contour data: that ROI cannot be meshed, the file's other ROIs can (as a
 *  structure set's ContourData that is no number fails its ROI alone). */
struct ContourDataFault
{
  std::string where, what;
};

[[noreturn]] void faulty(const std::string& where, const std::string& what)
{
  throw ContourDataFault{ where, what };
}

double coordinate(const Json& value, const std::string& where)
{
  if (!value.is_number())
    faulty(where, "a coordinate is not a number");
  const double number = value.get<double>();
  if (!std::isfinite(number))
    faulty(where, "a coordinate is not finite");
  return number;
}

/** The ROI's contours from its "slices" (`at`: where the ROI is in the file, for messages). */
void readSlices(const Json& roi, const std::string& at, double sign, PlanarStructure& structure)
{
  std::string zDisagrees; // the first slice whose points' z is not its own "z"
  const Json slices = roi.value("slices", Json::array());
  if (!slices.is_array())
    faulty(at + ".slices", "not an array");
  for (std::size_t s = 0; s < slices.size(); ++s)
  {
    const Json& slice = slices[s];
    const std::string sliceAt = at + ".slices[" + std::to_string(s) + "]";
    if (!slice.is_object() || !slice.contains("polygons") || !slice["polygons"].is_array())
      faulty(sliceAt, "expected an object with a \"polygons\" array");
    const bool hasZ = slice.contains("z");
    const double z = hasZ ? coordinate(slice["z"], sliceAt + ".z") : 0.0;
    const Json& polygons = slice["polygons"];
    for (std::size_t p = 0; p < polygons.size(); ++p)
    {
      const std::string polygonAt = sliceAt + ".polygons[" + std::to_string(p) + "]";
      if (!polygons[p].is_array())
        faulty(polygonAt, "a polygon is not an array of points");
      Polygon3 contour;
      for (const Json& point : polygons[p])
      {
        if (!point.is_array() || !(point.size() == 3 || (point.size() == 2 && hasZ)))
          faulty(polygonAt, hasZ ? "a point needs [x, y] or [x, y, z]" : "a point needs [x, y, z] (or the slice a \"z\")");
        const double x = coordinate(point[0], polygonAt), y = coordinate(point[1], polygonAt);
        contour.push_back({ sign * x, sign * y, point.size() == 3 ? coordinate(point[2], polygonAt) : z });
        if (hasZ && point.size() == 3 && zDisagrees.empty() &&
            std::abs(contour.back().z - z) > 1e-6 * std::max(1.0, std::abs(z)))
          zDisagrees = sliceAt;
      }
      structure.contours.push_back(std::move(contour));
    }
  }
  if (!zDisagrees.empty())
    structure.notes.push_back(zDisagrees + " has points whose z is not its \"z\": the points' own are used");
}

StructureSet readDocument(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw Error("cannot read '" + path + "': no such file or not readable");
  Json document;
  try
  {
    document = Json::parse(in);
  }
  catch (const Json::exception& e) // a syntax error, or a number beyond a double's range
  {
    throw Error("cannot read '" + path + "' as JSON: " + messageOf(e));
  }
  if (!document.is_object() || !document.contains("rois") || !document["rois"].is_array())
    malformed(path, "top level", "expected an object with a \"rois\" array");
  const std::string system = document.value("coordinateSystem", std::string("LPS"));
  if (system != "LPS" && system != "RAS")
    malformed(path, "coordinateSystem", "'" + system + "' is not LPS or RAS");
  const double sign = system == "RAS" ? -1.0 : 1.0; // RAS -> LPS: x and y change sign

  StructureSet set;
  const Json& rois = document["rois"];
  for (std::size_t r = 0; r < rois.size(); ++r)
  {
    const Json& roi = rois[r];
    const std::string at = "rois[" + std::to_string(r) + "]";
    if (!roi.is_object())
      malformed(path, at, "an ROI is not an object");
    PlanarStructure structure;
    structure.number = static_cast<int>(r + 1);
    if (roi.contains("number"))
    {
      if (!roi["number"].is_number_integer())
        malformed(path, at + ".number", "not an integer");
      structure.number = roi["number"].get<int>();
    }
    if (roi.contains("name") && !roi["name"].is_string())
      malformed(path, at + ".name", "not a string");
    structure.name = roi.value("name", std::string("ROI_") + std::to_string(structure.number));
    if (roi.contains("color"))
    {
      const Json& color = roi["color"];
      if (!color.is_array() || color.size() != 3)
        malformed(path, at + ".color", "expected [red, green, blue], 0..255");
      for (int c = 0; c < 3; ++c)
      {
        if (!color[c].is_number() || color[c].get<double>() < 0.0 || color[c].get<double>() > 255.0)
          malformed(path, at + ".color", "expected [red, green, blue], 0..255");
        structure.rgb[c] = static_cast<unsigned char>(color[c].get<double>() + 0.5);
      }
    }
    try
    {
      // A misspelt key ("Slices") left the ROI without contours, said only as "no closed contour".
      for (const auto& item : roi.items())
        if (item.key() != "number" && item.key() != "name" && item.key() != "color" && item.key() != "slices")
          throw ContourDataFault{ at, "unknown key \"" + item.key() + "\" (an ROI has number, name, color and slices)" };
      readSlices(roi, at, sign, structure);
    }
    catch (const ContourDataFault& fault)
    {
      structure.contours.clear();
      structure.notes.clear();
      structure.unusableBecause = fault.where + ": " + fault.what;
    }
    set.structures.push_back(std::move(structure));
  }
  if (set.structures.empty())
    malformed(path, "rois", "no ROI");
  markSharedRoiNumbers(set, path, "one number cannot name two meshes, so none of them is meshed",
                       "one number cannot name two meshes");
  return set;
}

} // namespace

StructureSet readContourJson(const std::string& path)
{
  try
  {
    return readDocument(path);
  }
  catch (const Json::exception& e)
  {
    // A value of the wrong type where a name or number was expected.
    throw Error("'" + path + "': " + messageOf(e));
  }
}

} // namespace slicemesh

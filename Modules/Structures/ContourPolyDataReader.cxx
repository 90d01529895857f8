// 3D Slicer's planar contour representation: a VTK polydata of closed polylines, one ROI per file,
// XML (.vtp, read by VTK) or legacy (.vtk, read by SliceMesh's own reader).
#include "LegacyPolyDataReader.h"
#include "Core/Lowercase.h"
#include "StructureSet.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_set>

namespace slicemesh
{
namespace
{

/** Collects the reader's error messages instead of VTK printing them. */
void recordError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  std::string& message = *static_cast<std::string*>(clientData);
  if (message.empty() && callData)
    message = static_cast<const char*>(callData);
}

/** The geometry of a VTK XML polydata file (.vtp), through VTK's reader. */
PolyDataGeometry readXmlPolyData(const std::string& path)
{
  std::string error;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(recordError);
  onError->SetClientData(&error);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* polyData = reader->GetOutput();
  if (!error.empty() || !polyData)
    throw Error("cannot read '" + path + "' as VTK polydata: " + (error.empty() ? "no data" : error.substr(0, error.find('\n'))));
  PolyDataGeometry geometry;
  geometry.points.resize(static_cast<std::size_t>(polyData->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < polyData->GetNumberOfPoints(); ++i)
    polyData->GetPoint(i, geometry.points[static_cast<std::size_t>(i)].data());
  auto cells = [](vtkCellArray* from, std::vector<std::vector<std::int64_t>>& to)
  {
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; from && c < from->GetNumberOfCells(); ++c)
    {
      from->GetCellAtId(c, ids);
      to.emplace_back(ids->begin(), ids->end());
    }
  };
  cells(polyData->GetLines(), geometry.lines);
  cells(polyData->GetPolys(), geometry.polygons);
  vtkFieldData* fields = polyData->GetFieldData();
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
    if (auto* strings = vtkStringArray::SafeDownCast(fields->GetAbstractArray(a)))
      if (strings->GetName() && strings->GetNumberOfValues() > 0)
        geometry.fieldStrings.emplace(strings->GetName(), strings->GetValue(0));
  return geometry;
}

/** The ROI's name: the LabelName field SliceMesh writes, else the file name without its extensions. */
std::string structureName(const PolyDataGeometry& geometry, const std::string& path)
{
  if (const auto name = geometry.fieldStrings.find("LabelName"); name != geometry.fieldStrings.end() && !name->second.empty())
    return name->second;
  std::string stem = std::filesystem::path(path).filename().string();
  return stem.substr(0, stem.find('.'));
}

} // namespace

/** Whether two polygon cells share an edge (by their point ids): the cells of a surface mesh do,
 *  contours drawn in planes never. A surface given as contours was read triangle by triangle, each
 *  a tilted "contour" skipped or a speck meshed, into a mesh of a tenth of its volume (exit 0). */
bool polygonsShareAnEdge(const std::vector<std::vector<std::int64_t>>& polygons)
{
  std::unordered_set<std::uint64_t> edges;
  for (const std::vector<std::int64_t>& ids : polygons)
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      const std::int64_t a = ids[i], b = ids[(i + 1) % ids.size()];
      if (a == b)
        continue;
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) ^ static_cast<std::uint64_t>(std::max(a, b));
      if (!edges.insert(key).second)
        return true;
    }
  return false;
}

StructureSet readContourPolyData(const std::string& path)
{
  if (!std::filesystem::is_regular_file(path))
    throw Error("cannot read '" + path + "': no such file");
  const bool xml = lowercase(std::filesystem::path(path).extension().string()) == ".vtp";
  const PolyDataGeometry geometry = xml ? readXmlPolyData(path) : readLegacyPolyData(path);
  // 3D Slicer marks its scene space (RAS) by a SPACE field (XML) or in the title (legacy).
  const auto space = geometry.fieldStrings.find("SPACE");
  const bool ras = (space != geometry.fieldStrings.end() && lowercase(space->second) == "ras") ||
                   lowercase(geometry.title).find("space=ras") != std::string::npos;

  if (polygonsShareAnEdge(geometry.polygons))
    throw Error("'" + path + "' holds a surface mesh (" + std::to_string(geometry.polygons.size()) +
                " polygons joined at their edges), not contours drawn in planes: SliceMesh meshes contours or a label map");
  PlanarStructure roi;
  roi.number = 1;
  roi.name = structureName(geometry, path);
  std::size_t open = 0;
  // RAS files are turned to LPS: x and y change sign.
  const double sign = ras ? -1.0 : 1.0;
  auto take = [&](const std::vector<std::vector<std::int64_t>>& cells, bool polygons)
  {
    for (const std::vector<std::int64_t>& ids : cells)
    {
      Polygon3 contour;
      for (const std::int64_t id : ids)
      {
        if (id < 0 || id >= static_cast<std::int64_t>(geometry.points.size()))
          throw Error("'" + path + "': a cell refers to point " + std::to_string(id) + " of " +
                      std::to_string(geometry.points.size()));
        const std::array<double, 3>& p = geometry.points[static_cast<std::size_t>(id)];
        // strtod and VTK both read "nan" and "inf", which no contour can be drawn through.
        if (!std::all_of(p.begin(), p.end(), [](double c) { return std::isfinite(c); }))
          throw Error("'" + path + "': point " + std::to_string(id) + " of a contour has a coordinate that is not a finite number");
        contour.push_back({ sign * p[0], sign * p[1], p[2] });
      }
      const bool closed = polygons || (ids.size() > 3 && (ids.front() == ids.back() || (contour.front().x == contour.back().x &&
                                                                                         contour.front().y == contour.back().y &&
                                                                                         contour.front().z == contour.back().z)));
      if (!closed)
      {
        ++open;
        continue;
      }
      roi.contours.push_back(std::move(contour));
    }
  };
  take(geometry.lines, false);
  take(geometry.polygons, true);
  if (open > 0)
    roi.notes.push_back(std::to_string(open) + " open polyline(s) skipped: only closed contours enclose a volume");
  StructureSet set;
  set.structures.push_back(std::move(roi));
  return set;
}

} // namespace slicemesh

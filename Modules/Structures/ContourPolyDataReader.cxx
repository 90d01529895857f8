// 3D Slicer's planar contour representation: a VTK polydata of closed polylines, one ROI per file.
#include "LegacyCellLists.h"
#include "StructureSet.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

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

std::string lowercase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** The ROI's name: the LabelName field SliceMesh writes, else the file name without its extensions. */
std::string structureName(vtkPolyData* polyData, const std::string& path)
{
  if (auto* names = vtkStringArray::SafeDownCast(polyData->GetFieldData()->GetAbstractArray("LabelName")))
    if (names->GetNumberOfValues() > 0 && !names->GetValue(0).empty())
      return names->GetValue(0);
  std::string stem = std::filesystem::path(path).filename().string();
  return stem.substr(0, stem.find('.'));
}

} // namespace

StructureSet readContourPolyData(const std::string& path)
{
  if (!std::filesystem::is_regular_file(path))
    throw Error("cannot read '" + path + "': no such file");
  std::string error;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(recordError);
  onError->SetClientData(&error);
  vtkSmartPointer<vtkPolyData> polyData;
  bool ras = false;
  if (lowercase(std::filesystem::path(path).extension().string()) == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, onError);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
    reader->SetFileName(path.c_str());
    reader->Update();
    polyData = reader->GetOutput();
    if (auto* space = vtkStringArray::SafeDownCast(polyData->GetFieldData()->GetAbstractArray("SPACE")))
      ras = space->GetNumberOfValues() > 0 && lowercase(space->GetValue(0)) == "ras";
  }
  else
  {
    if (const auto fault = legacyCellListFault(path))
      throw Error("cannot read '" + path + "' as VTK polydata: " + *fault);
    vtkNew<vtkPolyDataReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, onError);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
    reader->SetFileName(path.c_str());
    reader->Update();
    polyData = reader->GetOutput();
    if (reader->GetHeader())
      ras = lowercase(reader->GetHeader()).find("space=ras") != std::string::npos;
  }
  if (!error.empty() || !polyData)
    throw Error("cannot read '" + path + "' as VTK polydata: " + (error.empty() ? "no data" : error.substr(0, error.find('\n'))));

  PlanarStructure roi;
  roi.number = 1;
  roi.name = structureName(polyData, path);
  std::size_t open = 0;
  // RAS files (3D Slicer's scene space) are turned to LPS: x and y change sign.
  const double sign = ras ? -1.0 : 1.0;
  auto take = [&](vtkCellArray* cells, bool polygons)
  {
    if (!cells)
      return;
    vtkNew<vtkIdList> ids;
    for (cells->InitTraversal(); cells->GetNextCell(ids);)
    {
      Polygon3 contour;
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        if (ids->GetId(i) < 0 || ids->GetId(i) >= polyData->GetNumberOfPoints())
          throw Error("'" + path + "': a cell refers to point " + std::to_string(ids->GetId(i)) + " of " +
                      std::to_string(polyData->GetNumberOfPoints()));
        double p[3];
        polyData->GetPoint(ids->GetId(i), p);
        contour.push_back({ sign * p[0], sign * p[1], p[2] });
      }
      const bool closed = polygons || (ids->GetNumberOfIds() > 3 &&
                                       (ids->GetId(0) == ids->GetId(ids->GetNumberOfIds() - 1) ||
                                        (contour.front().x == contour.back().x && contour.front().y == contour.back().y &&
                                         contour.front().z == contour.back().z)));
      if (!closed)
      {
        ++open;
        continue;
      }
      roi.contours.push_back(std::move(contour));
    }
  };
  take(polyData->GetLines(), false);
  take(polyData->GetPolys(), true);
  if (open > 0)
    roi.notes.push_back(std::to_string(open) + " open polyline(s) skipped: only closed contours enclose a volume");
  StructureSet set;
  set.structures.push_back(std::move(roi));
  return set;
}

} // namespace slicemesh

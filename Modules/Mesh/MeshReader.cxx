#include "MeshReader.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>

namespace slicemesh
{
namespace
{

vtkSmartPointer<vtkPolyData> readPolyData(const std::string& path)
{
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    if (!reader->CanReadFile(path.c_str()))
      throw Error("cannot read mesh '" + path + "': not a VTK XML polydata file");
    reader->Update();
    return reader->GetOutput();
  }
  if (extension == ".vtk")
  {
    vtkNew<vtkPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    if (!reader->IsFilePolyData())
      throw Error("cannot read mesh '" + path + "': not a VTK polydata file");
    reader->Update();
    return reader->GetOutput();
  }
  throw Error("cannot read mesh '" + path + "': only .vtp and .vtk are read");
}

} // namespace

MeshFile readMesh(const std::string& path)
{
  const vtkSmartPointer<vtkPolyData> polyData = readPolyData(path);
  MeshFile file;
  TriangleMesh& mesh = file.mesh;
  for (vtkIdType n = 0; n < polyData->GetNumberOfPoints(); ++n)
  {
    double p[3];
    polyData->GetPoint(n, p);
    mesh.points.push_back({ p[0], p[1], p[2] });
  }
  vtkCellArray* polys = polyData->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  std::vector<vtkIdType> triangleCells; // cell ids of the triangles, for the cell arrays
  vtkIdType cell = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids); ++cell)
    if (count == 3)
    {
      mesh.triangles.push_back({ static_cast<std::int32_t>(ids[0]), static_cast<std::int32_t>(ids[1]),
                                 static_cast<std::int32_t>(ids[2]) });
      triangleCells.push_back(cell);
    }

  MeshAttributes& attributes = file.attributes;
  if (vtkDataArray* labels = polyData->GetCellData()->GetArray("Label"))
    for (vtkIdType c : triangleCells)
      attributes.cellLabels.push_back(static_cast<int>(labels->GetComponent(c, 0)));
  if (vtkDataArray* colors = polyData->GetCellData()->GetArray("Color"))
    for (vtkIdType c : triangleCells)
      attributes.cellColors.push_back({ static_cast<unsigned char>(colors->GetComponent(c, 0)),
                                        static_cast<unsigned char>(colors->GetComponent(c, 1)),
                                        static_cast<unsigned char>(colors->GetComponent(c, 2)) });
  vtkFieldData* field = polyData->GetFieldData();
  auto* names = vtkStringArray::SafeDownCast(field->GetAbstractArray("LabelName"));
  vtkDataArray* values = field->GetArray("LabelValue");
  vtkDataArray* rgba = field->GetArray("LabelColor");
  if (names)
    for (vtkIdType n = 0; n < names->GetNumberOfValues(); ++n)
    {
      MeshAttributes::Structure structure;
      structure.name = names->GetValue(n);
      if (values && n < values->GetNumberOfTuples())
        structure.value = static_cast<int>(values->GetComponent(n, 0));
      if (rgba && n < rgba->GetNumberOfTuples())
        for (int k = 0; k < 4; ++k)
          structure.rgba[k] = static_cast<unsigned char>(std::lround(255.0 * rgba->GetComponent(n, k)));
      attributes.structures.push_back(structure);
    }
  return file;
}

} // namespace slicemesh

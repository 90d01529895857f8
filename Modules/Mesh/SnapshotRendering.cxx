// The snapshot rendered with VTK through OpenGL: the plugin SliceMeshSnapshotRendering.
#include "SnapshotPlugin.h"

#include "FileReplacement.h"

#include "Measures/MeshQuality.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <X11/Xlib.h>
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace slicemesh
{
namespace
{

bool displayAvailable(std::string* reason)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    if (reason)
      *reason = "no X display (DISPLAY is not set); run under xvfb-run";
    return false;
  }
  // The probe's connection stays open until the program ends: closing the server's last client
  // makes an Xvfb started without -noreset (as xvfb-run starts it) reset, and a renderer that
  // connects during the reset, a fraction of a second later, fails ("bad X server connection").
  static Display* connection = nullptr;
  if (!connection)
    connection = XOpenDisplay(nullptr);
  if (!connection)
  {
    if (reason)
      *reason = std::string("cannot open the X display '") + display + "'; run under xvfb-run";
    return false;
  }
  return true;
}

/** The checks every snapshot makes before rendering: a display, triangles, a folder. */
void checkSnapshotTarget(const TriangleMesh& mesh, const std::string& path)
{
  std::string reason;
  if (!displayAvailable(&reason))
    throw Error("cannot render snapshot '" + path + "': " + reason);
  if (mesh.triangles.empty())
    throw Error("cannot render snapshot '" + path + "': the mesh has no triangles");
  writablePlace(path, "snapshot");
}

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].x, mesh.points[i].y, mesh.points[i].z);
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()), 3 * static_cast<vtkIdType>(mesh.triangles.size()));
  for (const Triangle& t : mesh.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    cells->InsertNextCell(3, ids);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(cells);
  return polyData;
}

/** Renders the actor off screen from the front-right-top, whole in view, on white, and writes the
 *  PNG atomically (a temporary name in the same folder, renamed when complete). */
void renderToPng(vtkActor* actor, const std::string& path, const SnapshotOptions& options)
{
#if defined(__SANITIZE_ADDRESS__)
  // The OpenGL driver VTK loads keeps a few allocations of its own (240 bytes) after the window is
  // gone and is unloaded by exit, so LeakSanitizer cannot even name it: not ours to report.
  __lsan::ScopedDisabler driverAllocations;
#endif
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  // LPS: the viewer's anterior is -P; look from anterior-right-superior, head up.
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(-1.0, -2.0, 1.2);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(options.width, options.height);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();

  FileReplacement file(path, "snapshot");
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(file.temporary().c_str());
  writer->Write();
  std::error_code error;
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(file.temporary(), error) ||
      std::filesystem::file_size(file.temporary(), error) == 0)
    throw Error("cannot write snapshot '" + path + "'");
  file.commit();
}

void writeQualitySnapshot(const TriangleMesh& mesh, const std::string& path, const SnapshotOptions& options)
{
  checkSnapshotTarget(mesh, path);
  const vtkSmartPointer<vtkPolyData> polyData = toPolyData(mesh);
  vtkNew<vtkDoubleArray> minAngle;
  minAngle->SetName("MinAngle");
  const std::vector<double> angles = triangleMinAngles(mesh);
  minAngle->SetNumberOfValues(static_cast<vtkIdType>(angles.size()));
  for (std::size_t i = 0; i < angles.size(); ++i)
    minAngle->SetValue(static_cast<vtkIdType>(i), angles[i]);
  polyData->GetCellData()->SetScalars(minAngle);

  vtkNew<vtkLookupTable> colours;
  colours->SetHueRange(0.0, 1.0 / 3.0); // red -> yellow -> green
  colours->SetSaturationRange(0.9, 0.9);
  colours->SetValueRange(1.0, 1.0);
  colours->SetNumberOfTableValues(256);
  colours->SetTableRange(0.0, options.goodAngleDegrees);
  colours->Build();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  mapper->SetLookupTable(colours);
  mapper->SetScalarModeToUseCellData();
  mapper->SetScalarRange(0.0, options.goodAngleDegrees);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.25, 0.25, 0.25);
  actor->GetProperty()->SetLineWidth(0.5);
  renderToPng(actor, path, options);
}

void writeStructureSnapshot(const TriangleMesh& meshes, const std::vector<std::array<unsigned char, 3>>& triangleColors,
                            const std::string& path, const SnapshotOptions& options)
{
  checkSnapshotTarget(meshes, path);
  if (triangleColors.size() != meshes.triangles.size())
    throw Error("cannot render snapshot '" + path + "': " + std::to_string(triangleColors.size()) + " colours for " +
                std::to_string(meshes.triangles.size()) + " triangles");
  const vtkSmartPointer<vtkPolyData> polyData = toPolyData(meshes);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Color");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(triangleColors.size()));
  for (std::size_t i = 0; i < triangleColors.size(); ++i)
    for (int c = 0; c < 3; ++c)
      colours->SetTypedComponent(static_cast<vtkIdType>(i), c, triangleColors[i][c]);
  polyData->GetCellData()->SetScalars(colours);

  // Vertex normals for smooth shading; the meshes are already outward oriented and share no
  // vertices, so no reorientation and no splitting at sharp edges beyond the default angle.
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(polyData);
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->SetFeatureAngle(60.0);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderToPng(actor, path, options);
}

} // namespace

} // namespace slicemesh

/** The plugin's entry: its table of functions (SnapshotPlugin.h). */
extern "C" __attribute__((visibility("default"))) const slicemesh::SnapshotFunctions* slicemeshSnapshotFunctions()
{
  static const slicemesh::SnapshotFunctions functions{ sizeof(slicemesh::SnapshotFunctions), &slicemesh::displayAvailable,
                                                       &slicemesh::writeQualitySnapshot, &slicemesh::writeStructureSnapshot };
  return &functions;
}

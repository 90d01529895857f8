#include "SlicerPipeline.h"

#include <vtkCellArray.h>
#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cmath>

namespace slicemesh
{

TriangleMesh slicerSurface(const MaskVolume* mask, double smoothing)
{
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  // Pad by one voxel; index space (spacing 1): the padded image starts at index -1.
  vtkNew<vtkImageData> image;
  image->SetOrigin(-1.0, -1.0, -1.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->SetDimensions(static_cast<int>(size[0] + 2), static_cast<int>(size[1] + 2), static_cast<int>(size[2] + 2));
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  std::fill(out, out + (size[0] + 2) * (size[1] + 2) * (size[2] + 2), 0);
  const unsigned char* in = mask->GetBufferPointer();
  for (std::size_t k = 0; k < size[2]; ++k)
    for (std::size_t j = 0; j < size[1]; ++j)
      for (std::size_t i = 0; i < size[0]; ++i)
        out[((k + 1) * (size[1] + 2) + (j + 1)) * (size[0] + 2) + (i + 1)] = in[(k * size[1] + j) * size[0] + i] ? 1 : 0;

  vtkNew<vtkDiscreteFlyingEdges3D> flyingEdges;
  flyingEdges->SetInputData(image);
  flyingEdges->SetValue(0, 1.0);
  flyingEdges->ComputeGradientsOff();
  flyingEdges->ComputeNormalsOff();
  flyingEdges->ComputeScalarsOff();
  vtkNew<vtkWindowedSincPolyDataFilter> smoother;
  smoother->SetInputConnection(flyingEdges->GetOutputPort());
  smoother->SetNumberOfIterations(static_cast<int>(20 + 40 * smoothing));
  smoother->SetPassBand(std::pow(10.0, -4.0 * smoothing));
  smoother->BoundarySmoothingOff();
  smoother->FeatureEdgeSmoothingOff();
  smoother->NonManifoldSmoothingOn();
  smoother->NormalizeCoordinatesOn();
  vtkNew<vtkPolyDataNormals> normals; // Slicer applies the transform, then the normals
  normals->SetInputConnection(smoother->GetOutputPort());
  normals->ConsistencyOn();
  normals->SplittingOff();
  normals->Update();

  vtkPolyData* smoothed = smoother->GetOutput();
  const auto spacing = mask->GetSpacing();
  TriangleMesh stackMesh;
  stackMesh.points.resize(static_cast<std::size_t>(smoothed->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < smoothed->GetNumberOfPoints(); ++i)
  {
    double p[3];
    smoothed->GetPoint(i, p);
    stackMesh.points[static_cast<std::size_t>(i)] = { p[0] * spacing[0], p[1] * spacing[1], p[2] * spacing[2] };
  }
  vtkCellArray* polys = smoothed->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
    if (ids->GetNumberOfIds() == 3)
      stackMesh.triangles.push_back({ static_cast<std::int32_t>(ids->GetId(0)), static_cast<std::int32_t>(ids->GetId(1)),
                                      static_cast<std::int32_t>(ids->GetId(2)) });
  return stackMesh;
}

} // namespace slicemesh

// SliceMesh against 3D Slicer's default label map -> closed surface conversion, on analytic
// phantoms: the same rasterized label map goes through both, and both meshes are measured against
// the exact surface. Not part of the test run; see the README for the command. SliceMesh runs as
// the CLI does by default: contours prepared by cli::prepareContours with the default options
// (Traced), the reconstruction, then the finishing stage (remeshed and smoothed in 3D); and the same
// with the smoothed tiling only, with the tiling as it is (the paper's surface), and with the tiling
// without Steiner points.
//
// Slicer's pipeline as in vtkBinaryLabelmapToClosedSurfaceConversionRule (Slicer 5.x, smoothing
// factor 0.5, decimation off): pad the label map by one voxel, vtkDiscreteFlyingEdges3D in index
// space, vtkWindowedSincPolyDataFilter (pass band 10^(-4 s), 20 + 40 s iterations, boundary and
// feature-edge smoothing off, non-manifold smoothing on, normalized coordinates), the image's
// index-to-physical transform, vtkPolyDataNormals (consistency on, splitting off).
#include "Box.h"
#include "CappedCylinder.h"
#include "ContourExtraction.h"
#include "Ellipsoid.h"
#include "MeshQuality.h"
#include "MeshValidation.h"
#include "MeshWriter.h"
#include "PhantomCombinators.h"
#include "PhantomGrid.h"
#include "Sphere.h"
#include "SurfaceFinishing.h"
#include "SurfaceReconstruction.h"
#include "ContourResampling.h"
#include "IntermediateSections.h"
#include "SliceMeshPipeline.h"
#include "Torus.h"

#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkWindowedSincPolyDataFilter.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace slicemesh;

namespace
{

using Clock = std::chrono::steady_clock;

struct Row
{
  std::string phantom, grid, method;
  double seconds = 0.0;
  std::size_t triangles = 0;
  double below30 = 0.0, minAngle = 0.0, meanDistance = 0.0, maxDistance = 0.0, volumeError = 0.0;
  bool valid = false;
  double spacingRatio = 0.0; ///< in-plane point spacing / slice spacing (SliceMesh rows)
};

void measure(Row& row, const TriangleMesh& physical, const Phantom& phantom)
{
  const MeshValidation v = validateMesh(physical);
  const MeshQuality q = measureMeshQuality(physical);
  row.triangles = q.triangles;
  row.below30 = 100.0 * q.fractionBelow30;
  row.minAngle = q.minAngleDegrees;
  row.valid = v.valid() || (v.closed() && v.manifold() && v.selfIntersections == 0 && v.volume < 0.0);
  row.volumeError = 100.0 * (std::abs(v.volume) / phantom.volume() - 1.0);
  double sum = 0.0;
  row.maxDistance = 0.0;
  for (const Point3& p : physical.points)
  {
    const double d = distanceToSurface(phantom, p);
    sum += d;
    row.maxDistance = std::max(row.maxDistance, d);
  }
  row.meanDistance = physical.points.empty() ? 0.0 : sum / physical.points.size();
}

/** SliceMesh as the CLI runs it by default (contour preparation included), with the preparation
 *  mode and the refinement as given. */
Row sliceMesh(const Phantom& phantom, const MaskVolume* mask, cli::ContourPreparation preparation, double minAngle,
              SurfaceFinish finish, const std::string& method)
{
  Row row;
  row.method = method;
  const auto began = Clock::now();
  cli::ContourPreparationOptions preparationOptions;
  preparationOptions.mode = preparation;
  const ContourStack stack = cli::maskContours(mask, cli::ContourOptions{}, preparationOptions);
  ReconstructionOptions options;
  options.minAngleDegrees = minAngle;
  const TriangleMesh tiling = reconstructSurface(stack, options);
  const auto spacing = mask->GetSpacing();
  SurfaceFinishingOptions finishing = finishingOptionsFor({ spacing[0], spacing[1], spacing[2] });
  finishing.finish = finish;
  const FinishedSurface finished = finishSurface(tiling, validateMesh(tiling), finishing);
  if (!finished.fallback.empty())
    std::fprintf(stderr, "\n%s: %s\n", method.c_str(), finished.fallback.c_str());
  const TriangleMesh physical = mapToPhysicalSpace(finished.mesh, sliceFrameOf(mask), CoordinateSystem::LPS);
  row.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  row.spacingRatio = meanPointSpacing(stack) / mask->GetSpacing()[2];
  measure(row, physical, phantom);
  return row;
}

Row slicerPipeline(const Phantom& phantom, const MaskVolume* mask, double smoothing = 0.5)
{
  Row row;
  row.method = "Slicer (flying edges + sinc)";
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  const auto began = Clock::now();
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
  smoother->Update();

  // Index space -> physical exactly as our own meshes: stack frame (index times spacing), then the frame.
  vtkPolyData* smoothed = smoother->GetOutput();
  const auto spacing = mask->GetSpacing();
  TriangleMesh stackMesh;
  stackMesh.points.resize(static_cast<std::size_t>(smoothed->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < smoothed->GetNumberOfPoints(); ++i)
  {
    double p[3];
    smoothed->GetPoint(i, p);
    stackMesh.points[i] = { p[0] * spacing[0], p[1] * spacing[1], p[2] * spacing[2] };
  }
  TriangleMesh physical = mapToPhysicalSpace(stackMesh, sliceFrameOf(mask), CoordinateSystem::LPS);
  normals->Update(); // timed as part of the pipeline (its output is not needed for the measures)
  row.seconds = std::chrono::duration<double>(Clock::now() - began).count();

  vtkCellArray* polys = smoothed->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
    if (ids->GetNumberOfIds() == 3)
      physical.triangles.push_back({ static_cast<std::int32_t>(ids->GetId(0)), static_cast<std::int32_t>(ids->GetId(1)),
                                     static_cast<std::int32_t>(ids->GetId(2)) });
  measure(row, physical, phantom);
  return row;
}

Matrix3 rotation(const Vector3& axis, double angle)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

} // namespace

int main(int argc, char* argv[])
{
  struct Named
  {
    const char* name;
    PhantomPointer phantom;
  };
  const std::vector<Named> phantoms = {
    { "sphere r20", std::make_shared<Sphere>(Vector3(0, 0, 0), 20.0) },
    { "ellipsoid 25x15x10 rotated", std::make_shared<Ellipsoid>(Vector3(1, 2, 3), Vector3(25, 15, 10), rotation({ 1, 2, 3 }, 0.7)) },
    { "cylinder r10 h40 tilted", std::make_shared<CappedCylinder>(Vector3(0, 0, 0), Vector3(0.3, 0.2, 1.0), 10.0, 20.0) },
    { "box 30x20x16 rotated", std::make_shared<Box>(Vector3(0, 0, 0), Vector3(15, 10, 8), rotation({ 0, 1, 1 }, 0.5)) },
    { "torus R18 r6", std::make_shared<Torus>(Vector3(0, 0, 0), Vector3(1, 0, 0.5), 18.0, 6.0) },
    { "hollow sphere r20/r10", std::make_shared<NestedSubtraction>(std::make_shared<Sphere>(Vector3(0, 0, 0), 20.0),
                                                                    std::make_shared<Sphere>(Vector3(0, 0, 0), 10.0)) },
    { "two spheres r10", std::make_shared<DisjointUnion>(std::make_shared<Sphere>(Vector3(-12, 0, 0), 10.0),
                                                          std::make_shared<Sphere>(Vector3(12, 0, 0), 10.0)) },
  };
  struct Grid
  {
    const char* name;
    std::array<double, 3> spacing;
  };
  const std::vector<Grid> grids = { { "1x1x1", { 1.0, 1.0, 1.0 } }, { "0.8x0.8x3", { 0.8, 0.8, 3.0 } } };

  std::vector<Row> rows;
  for (const Named& named : phantoms)
    for (const Grid& grid : grids)
    {
      const GridSpec spec = gridAround(*named.phantom, grid.spacing, 2);
      const MaskVolume::Pointer mask = rasterizePhantom(*named.phantom, spec);
      // The default (finished), the smoothed tiling, the tiling, the tiling without refinement.
      const cli::ContourPreparation byDefault = cli::ContourPreparationOptions{}.mode;
      for (Row row : { sliceMesh(*named.phantom, mask, byDefault, 30.0, SurfaceFinish::Remeshed, "SliceMesh (default: remeshed)"),
                       sliceMesh(*named.phantom, mask, byDefault, 30.0, SurfaceFinish::Smoothed, "SliceMesh, smoothed tiling"),
                       sliceMesh(*named.phantom, mask, byDefault, 30.0, SurfaceFinish::Tiled, "SliceMesh, tiling (paper)"),
                       sliceMesh(*named.phantom, mask, byDefault, 0.0, SurfaceFinish::Tiled, "SliceMesh, tiling, no Steiner"),
                       slicerPipeline(*named.phantom, mask) })
      {
        row.phantom = named.name;
        row.grid = grid.name;
        rows.push_back(row);
        std::fprintf(stderr, ".");
      }
    }
  std::fprintf(stderr, "\n");

  std::string table =
    "| phantom | grid (mm) | method | time (s) | triangles | < 30° | min angle | mean dist (mm) | max dist (mm) | volume error | valid |\n"
    "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  char line[512];
  for (const Row& r : rows)
  {
    std::snprintf(line, sizeof line, "| %s | %s | %s | %.3f | %zu | %.1f%% | %.1f° | %.3f | %.3f | %+.2f%% | %s |\n",
                  r.phantom.c_str(), r.grid.c_str(), r.method.c_str(), r.seconds, r.triangles, r.below30, r.minAngle,
                  r.meanDistance, r.maxDistance, r.volumeError, r.valid ? "yes" : "NO");
    table += line;
  }
  std::printf("%s", table.c_str());
  // The in-plane point spacing / slice spacing ratio that dominates the angle figures.
  std::printf("\nratio of in-plane point spacing to slice spacing (SliceMesh default contours):");
  for (const Row& r : rows)
    if (r.method.rfind("SliceMesh (", 0) == 0)
      std::printf(" %s %s %.2f;", r.phantom.c_str(), r.grid.c_str(), r.spacingRatio);
  std::printf("\n");

  // The implicit (RBF) intermediate sections of issue 3: fit and extraction time against contour
  // size, on two circles 12 mm apart (slices far thicker than the point spacing, so the slab gets
  // sections); the fit subsamples its constraints to a fixed budget of centres.
  std::printf("\n| points per contour | sections | centres in the fit | fit (s) | extraction (s) |\n|---:|---:|---:|---:|---:|\n");
  for (int points : { 500, 1000, 3000, 10000 })
  {
    ContourStack stack;
    for (double z : { 0.0, 12.0 })
    {
      Polygon2 circle;
      for (int i = 0; i < points; ++i)
        circle.push_back({ 20.0 * std::cos(2 * M_PI * i / points), 20.0 * std::sin(2 * M_PI * i / points) });
      stack.slices.push_back({ z, { circle } });
    }
    UndersamplingOptions options;
    options.maxSliceSpacingFactor = 2.0;
    SectionStatistics statistics;
    insertIntermediateSections(stack, options, &statistics);
    std::printf("| %d | %zu | %zu | %.3f | %.3f |\n", points, statistics.sectionsInserted, statistics.largestFit,
                statistics.fitSeconds, statistics.extractSeconds);
  }
  if (argc > 1)
    std::ofstream(argv[1]) << table;
  return 0;
}

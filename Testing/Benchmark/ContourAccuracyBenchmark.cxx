// How close the surface SliceMesh makes from planar contours comes to the true one. Analytic
// phantoms are contoured as a planning system draws them: one closed polygon per piece of each
// slice, its points on the shape's true outline at irregular steps along it. Each is written as an
// RT structure set, meshed by the SliceMesh executable given (as a user runs it, with the extra
// arguments given) and measured with the phantom's distance function: at every vertex, and over the
// surface at the triangles' centroids. One-sided (the mesh against the shape): a part of the shape
// the mesh leaves out shows in the volume, not in the distances.
//   ContourAccuracyBenchmark <SliceMesh executable> <work folder> [extra SliceMesh arguments...]
// Prints one row per phantom, slice spacing and point spacing, then the means.
#include "BenchmarkPhantoms.h"
#include "Contours/MarchingSquares.h"
#include "Core/AreaNormal.h"
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "MeshReader.h"
#include "PhantomGrid.h"
#include "PhantomStructureSet.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

using namespace slicemesh;

namespace
{

using Polygon3 = std::vector<Point3>; ///< a closed contour of one slice

/** Sampling of the signed distance within a slice: the outline found on it lies within a few
 *  micrometres of the true one, far below any point spacing measured. */
constexpr double outlineCell = 0.1;

/** Points at irregular steps along the closed polyline `outline`, about `spacing` apart on average
 *  (each step's position moved by up to 35% of a step, as a planner clicks or a tool resamples). */
Polygon3 planningContour(const Polygon2& outline, double z, double spacing, std::mt19937& random)
{
  std::vector<double> along(outline.size() + 1, 0.0);
  for (std::size_t i = 0; i < outline.size(); ++i)
    along[i + 1] = along[i] + distance(outline[i], outline[(i + 1) % outline.size()]);
  const double length = along.back();
  const int points = std::max(8, static_cast<int>(std::lround(length / spacing)));
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  Polygon3 contour;
  std::size_t segment = 0;
  for (int k = 0; k < points; ++k)
  {
    const double at = length * (k + (k == 0 ? 0.0 : jitter(random))) / points;
    while (segment + 1 < outline.size() && along[segment + 1] < at)
      ++segment;
    const Point2& a = outline[segment];
    const Point2& b = outline[(segment + 1) % outline.size()];
    const double span = along[segment + 1] - along[segment];
    const double t = span > 0.0 ? (at - along[segment]) / span : 0.0;
    contour.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), z });
  }
  return contour;
}

/** The phantom's contours on axial slices `sliceSpacing` apart (placed off the shape's centre, as CT
 *  slices fall), points about `pointSpacing` apart. */
std::vector<Polygon3> contoured(const Phantom& phantom, double sliceSpacing, double pointSpacing, std::mt19937& random)
{
  std::vector<Polygon3> contours;
  const Bounds bounds = phantom.bounds();
  const Box2 box{ bounds.lower.x() - 1.0, bounds.lower.y() - 1.0, bounds.upper.x() + 1.0, bounds.upper.y() + 1.0 };
  for (double z = bounds.lower.z() + 0.37 * sliceSpacing; z < bounds.upper.z(); z += sliceSpacing)
  {
    const ScalarGrid2 grid = sampleGrid(box, outlineCell,
                                        [&](const std::vector<Point2>& nodes, std::vector<double>& values)
                                        {
                                          for (const Point2& p : nodes)
                                            values.push_back(phantom.signedDistance(Vector3(p.x, p.y, z)));
                                        });
    for (const Polygon2& outline : zeroContours(grid, 4.0 * outlineCell * outlineCell))
      contours.push_back(planningContour(outline, z, pointSpacing, random));
  }
  return contours;
}

struct Row
{
  bool meshed = false, valid = false;
  double seconds = 0.0, meanDistance = 0.0, maxDistance = 0.0, volumeError = 0.0, below30 = 0.0, minAngle = 0.0;
  double surfaceDistance = 0.0; ///< over the surface, not only its vertices: at the triangles' centroids, by area
  std::size_t triangles = 0;
};

Row meshAndMeasure(const Phantom& phantom, const std::vector<Polygon3>& contours, const std::string& executable,
                   const std::string& arguments, const std::filesystem::path& folder)
{
  const std::string structureSet = (folder / "RS.dcm").string(), mesh = (folder / "mesh.vtp").string();
  std::filesystem::remove(mesh);
  writePhantomStructureSet(structureSet, contours);
  const std::string command = "\"" + executable + "\" " + arguments + " \"" + structureSet + "\" \"" + mesh + "\" >/dev/null 2>&1";
  Row row;
  const auto began = std::chrono::steady_clock::now();
  row.meshed = std::system(command.c_str()) == 0;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  if (!row.meshed)
    return row;
  const TriangleMesh surface = readMesh(mesh).mesh; // LPS, the contours' own millimetres
  const MeshValidation validation = validateMesh(surface);
  const MeshQuality quality = measureMeshQuality(surface);
  row.valid = validation.valid();
  row.triangles = quality.triangles;
  row.below30 = 100.0 * quality.fractionBelow30;
  row.minAngle = quality.minAngleDegrees;
  row.volumeError = 100.0 * (std::abs(validation.volume) / phantom.volume() - 1.0);
  const VertexDistances distances = vertexDistances(phantom, surface);
  row.meanDistance = distances.mean;
  row.maxDistance = distances.max;
  // A surface whose vertices sit on the contours can still cut the corners between them: measured
  // at the triangles' centroids too, each counting for its area.
  double weighted = 0.0, area = 0.0;
  for (const Triangle& t : surface.triangles)
  {
    const Point3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    const Point3 n = areaNormal(a, b, c);
    const double triangleArea = 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    weighted += triangleArea * distanceToSurface(phantom, { (a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0, (a.z + b.z + c.z) / 3.0 });
    area += triangleArea;
  }
  row.surfaceDistance = area > 0.0 ? weighted / area : 0.0;
  return row;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: ContourAccuracyBenchmark <SliceMesh executable> <work folder> [extra SliceMesh arguments...]\n");
    return 2;
  }
  const std::string executable = argv[1];
  const std::filesystem::path folder = argv[2];
  std::filesystem::create_directories(folder);
  std::string arguments;
  for (int i = 3; i < argc; ++i)
    arguments += "'" + std::string(argv[i]) + "' ";

  std::vector<NamedPhantom> phantoms = benchmarkPhantoms();
  phantoms.push_back(branchingTubes());
  std::printf("| phantom | slices (mm) | points (mm) | mean dist, vertices (mm) | mean dist, surface (mm) | max dist (mm) | "
              "volume | triangles | < 30° | min angle | valid | s |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n");
  double distanceSum = 0.0, surfaceSum = 0.0, volumeSum = 0.0, seconds = 0.0, worstBelow30 = 0.0, smallestAngle = 180.0;
  int rows = 0, valid = 0;
  unsigned int caseNumber = 0;
  for (const NamedPhantom& named : phantoms)
    for (const double sliceSpacing : { 2.0, 3.0 })
      for (const double pointSpacing : { 1.0, 2.5 })
      {
        std::mt19937 random(2026 + caseNumber++); // a case's points do not depend on the cases before it
        const std::vector<Polygon3> contours = contoured(*named.phantom, sliceSpacing, pointSpacing, random);
        const Row row = meshAndMeasure(*named.phantom, contours, executable, arguments, folder);
        if (!row.meshed)
        {
          std::printf("| %s | %.1f | %.1f | failed | | | | | | | | |\n", named.name.c_str(), sliceSpacing, pointSpacing);
          continue;
        }
        std::printf("| %s | %.1f | %.1f | %.4f | %.4f | %.3f | %+.2f%% | %zu | %.2f%% | %.1f° | %s | %.2f |\n",
                    named.name.c_str(), sliceSpacing, pointSpacing, row.meanDistance, row.surfaceDistance, row.maxDistance,
                    row.volumeError, row.triangles, row.below30, row.minAngle, row.valid ? "yes" : "no", row.seconds);
        std::fflush(stdout);
        distanceSum += row.meanDistance;
        surfaceSum += row.surfaceDistance;
        worstBelow30 = std::max(worstBelow30, row.below30);
        smallestAngle = std::min(smallestAngle, row.minAngle);
        volumeSum += std::abs(row.volumeError);
        seconds += row.seconds;
        valid += row.valid ? 1 : 0;
        ++rows;
      }
  if (rows > 0)
    std::printf("\n%d cases, %d valid; mean distance %.4f mm at the vertices, %.4f mm over the surface; mean |volume "
                "error| %.2f%%; at most %.2f%% of a case's triangles under 30°, smallest angle %.1f°; %.1f s meshing\n",
                rows, valid, distanceSum / rows, surfaceSum / rows, volumeSum / rows, worstBelow30, smallestAngle, seconds);
  return 0;
}

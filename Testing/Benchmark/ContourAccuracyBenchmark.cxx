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
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "MeshReader.h"
#include "PhantomGrid.h"
#include "PhantomStructureSet.h"
#include "PlannerContours.h"

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
  row.surfaceDistance = meanSurfaceDistance(phantom, surface);
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
        const std::vector<Polygon3> contours = plannerContours(*named.phantom, sliceSpacing, pointSpacing, random);
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

// SliceMesh against 3D Slicer's default label map -> closed surface conversion, on analytic
// phantoms: the same rasterized label map goes through both, and both meshes are measured against
// the exact surface. Not part of the test run; see the README for the command. SliceMesh runs as
// the CLI does by default (meshMask, the one meshing path): contours with the default preparation
// (Traced), the reconstruction, then the finishing stage (remeshed and smoothed in 3D); and the same
// with the smoothed tiling only, with the tiling as it is (the paper's surface), and with the tiling
// without Steiner points.
//
// Slicer's pipeline as in vtkBinaryLabelmapToClosedSurfaceConversionRule (Slicer 5.x, smoothing
// factor 0.5, decimation off): pad the label map by one voxel, vtkDiscreteFlyingEdges3D in index
// space, vtkWindowedSincPolyDataFilter (pass band 10^(-4 s), 20 + 40 s iterations, boundary and
// feature-edge smoothing off, non-manifold smoothing on, normalized coordinates), the image's
// index-to-physical transform, vtkPolyDataNormals (consistency on, splitting off).
#include "BenchmarkPhantoms.h"
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "MeshWriter.h"
#include "PhantomGrid.h"
#include "Sections/IntermediateSections.h"
#include "MaskFileWriter.h"
#include "MaskMeshing.h"
#include "SlicerPipeline.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
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
  double voxelVolumeError = 0.0; ///< enclosed volume against the mask's voxels (%)
  bool valid = false;
  double spacingRatio = 0.0; ///< in-plane point spacing / slice spacing (SliceMesh rows)
};

void measure(Row& row, const TriangleMesh& physical, const Phantom& phantom, const MaskVolume* mask)
{
  const MeshValidation v = validateMesh(physical);
  row.voxelVolumeError = 100.0 * (std::abs(v.volume) / maskVoxelVolume(mask) - 1.0);
  const MeshQuality q = measureMeshQuality(physical);
  row.triangles = q.triangles;
  row.below30 = 100.0 * q.fractionBelow30;
  row.minAngle = q.minAngleDegrees;
  row.valid = v.valid() || (v.closed() && v.manifold() && v.selfIntersections == 0 && v.volume < 0.0);
  row.volumeError = 100.0 * (std::abs(v.volume) / phantom.volume() - 1.0);
  const VertexDistances distances = vertexDistances(phantom, physical);
  row.meanDistance = distances.mean;
  row.maxDistance = distances.max;
}

/** SliceMesh as the CLI runs it (meshMask, the one meshing path), with the contour preparation,
 *  the refinement's angle and the finish as given. */
Row sliceMesh(const Phantom& phantom, const MaskVolume* mask, ContourPreparation preparation, double minAngle,
              SurfaceFinish finish, const std::string& method)
{
  Row row;
  row.method = method;
  const auto began = Clock::now();
  MeshingOptions options;
  options.contours.mode = preparation;
  options.reconstruction.minAngleDegrees = minAngle;
  options.finishing.finish = finish;
  const MeshedMask meshed = meshMask(mask, options);
  if (!meshed.meshing.surface.fallback.empty())
    std::fprintf(stderr, "\n%s: %s\n", method.c_str(), meshed.meshing.surface.fallback.c_str());
  row.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  row.spacingRatio = meshed.meshing.measures.pointSpacing / mask->GetSpacing()[2];
  measure(row, meshed.physical, phantom, mask);
  return row;
}

Row slicerPipeline(const Phantom& phantom, const MaskVolume* mask)
{
  Row row;
  row.method = "Slicer (flying edges + sinc)";
  const auto began = Clock::now();
  // Index space -> physical exactly as our own meshes: stack frame (index times spacing), then the frame.
  const TriangleMesh physical = mapToPhysicalSpace(slicerSurface(mask), sliceFrameOf(mask), CoordinateSystem::LPS);
  row.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  measure(row, physical, phantom, mask);
  return row;
}

/** The grids of the targets table beyond the quality table's two: isotropic, near-isotropic
 *  (slices up to 1.4 pixels thick, where the traced contours are or are just no longer resampled)
 *  and thick-slice grids. */
std::vector<BenchmarkGrid> targetGrids()
{
  return { { "0.5x0.5x0.5", { 0.5, 0.5, 0.5 } }, { "0.7x0.7x0.7", { 0.7, 0.7, 0.7 } },
           { "0.5x0.5x0.7", { 0.5, 0.5, 0.7 } }, { "0.8x0.8x0.9", { 0.8, 0.8, 0.9 } },
           { "0.7x0.7x1.5", { 0.7, 0.7, 1.5 } }, { "0.8x0.8x3", { 0.8, 0.8, 3.0 } },
           { "0.9x0.9x2", { 0.9, 0.9, 2.0 } },   { "1x1x3", { 1.0, 1.0, 3.0 } } };
}

/** Grids written as "0.5x0.5x0.7,1x1x2.5" (mm, x by y by slice); empty when a grid does not parse. */
std::optional<std::vector<BenchmarkGrid>> parsedGrids(const std::string& text)
{
  std::vector<BenchmarkGrid> grids;
  std::stringstream list(text);
  for (std::string name; std::getline(list, name, ',');)
  {
    BenchmarkGrid grid{ name, {} };
    char x1 = 0, x2 = 0;
    std::istringstream in(name);
    if (!(in >> grid.spacing[0] >> x1 >> grid.spacing[1] >> x2 >> grid.spacing[2]) || x1 != 'x' || x2 != 'x' ||
        !(in >> std::ws).eof() || !(grid.spacing[0] > 0.0 && grid.spacing[1] > 0.0 && grid.spacing[2] > 0.0))
      return std::nullopt;
    grids.push_back(grid);
  }
  if (grids.empty())
    return std::nullopt;
  return grids;
}

/** What the default misses of its targets against Slicer's pipeline in one case (mean distance and
 *  triangles at most Slicer's, under 1% of triangles under 30 degrees, valid, enclosed volume at
 *  least as close to the voxels' as Slicer's), as " distance triangles ..."; empty when it meets all. */
std::string missedTargets(const Row& ours, const Row& slicer)
{
  std::string misses;
  if (ours.meanDistance > slicer.meanDistance)
    misses += " distance";
  if (ours.triangles > slicer.triangles)
    misses += " triangles";
  if (ours.below30 >= 1.0)
    misses += " angles";
  if (!ours.valid)
    misses += " validity";
  if (std::abs(ours.voxelVolumeError) > std::abs(slicer.voxelVolumeError))
    misses += " volume";
  return misses;
}

/** Where placement p puts a phantom on its grid: the grid moved by these fractions of a voxel along
 *  its axes. Placement 0 is the grid as gridAround lays it; the others follow Roberts' R3 sequence,
 *  which spreads any number of placements evenly over the voxel. A sphere's distance to the true
 *  surface depends on where its terraces fall on the voxels, on both sides of the comparison: one
 *  placement can make either look better. */
std::array<double, 3> placementShift(int p)
{
  const double phi = 1.2207440846057596; // the root of x^4 = x + 1
  std::array<double, 3> shift{};
  double step = 1.0;
  for (double& fraction : shift)
  {
    step /= phi;
    fraction = std::fmod(p * step, 1.0);
  }
  return shift;
}

/** The default against Slicer's pipeline on grids and shapes beyond the table's, each phantom at
 *  `placements` placements on each grid (placementShift): one row per case, or per phantom and grid
 *  with the means over its placements and how many of them meet every target. With `missedFolder`,
 *  the label map of each case that misses a target is written there, to be meshed again by the CLI. */
std::string targetsTable(const std::vector<BenchmarkGrid>& grids, int placements = 1, const std::string& missedFolder = {})
{
  std::vector<NamedPhantom> phantoms = benchmarkPhantoms();
  phantoms.push_back(branchingTubes());
  phantoms.push_back(thinPlate());
  std::string table =
    placements == 1
      ? "| phantom | grid (mm) | mean dist: SliceMesh / Slicer (mm) | triangles: SliceMesh / Slicer | < 30° | "
        "volume vs voxels: SliceMesh / Slicer | valid | targets |\n|---|---|---:|---:|---:|---:|---|---|\n"
      : "| phantom | grid (mm) | placements meeting every target | mean dist: SliceMesh / Slicer (mm), mean | "
        "triangles: SliceMesh / Slicer, mean | < 30°, largest | misses |\n|---|---|---:|---:|---:|---:|---|\n";
  std::size_t met = 0, cases = 0;
  char line[512];
  for (const NamedPhantom& named : phantoms)
    for (const BenchmarkGrid& grid : grids)
    {
      int metHere = 0;
      double distance[2] = { 0.0, 0.0 }, triangles[2] = { 0.0, 0.0 }, below30 = 0.0;
      std::map<std::string, int> missCounts;
      for (int p = 0; p < placements; ++p)
      {
        GridSpec spec = gridAround(*named.phantom, grid.spacing, 2);
        const std::array<double, 3> shift = placementShift(p);
        for (int axis = 0; axis < 3; ++axis)
          spec.origin[axis] += shift[axis] * grid.spacing[axis];
        const MaskVolume::Pointer mask = rasterizePhantom(*named.phantom, spec);
        const Row ours = sliceMesh(*named.phantom, mask, ContourPreparationOptions{}.mode, 30.0, SurfaceFinish::Remeshed, "default");
        const Row slicer = slicerPipeline(*named.phantom, mask);
        const std::string misses = missedTargets(ours, slicer);
        ++cases;
        met += misses.empty();
        metHere += misses.empty();
        distance[0] += ours.meanDistance / placements;
        distance[1] += slicer.meanDistance / placements;
        triangles[0] += static_cast<double>(ours.triangles) / placements;
        triangles[1] += static_cast<double>(slicer.triangles) / placements;
        below30 = std::max(below30, ours.below30);
        std::istringstream words(misses);
        for (std::string word; words >> word;)
          ++missCounts[word];
        if (!misses.empty() && !missedFolder.empty())
        {
          std::string name = named.name + "-" + grid.name + "-placement" + std::to_string(p) + ".nrrd";
          std::replace(name.begin(), name.end(), ' ', '-');
          std::replace(name.begin(), name.end(), '/', '-');
          writeMaskFile(mask, missedFolder + "/" + name);
        }
        if (placements > 1 && !misses.empty()) // the case to look at again
          std::fprintf(stderr, "\n%s, %s, placement %d (grid moved by %.3f, %.3f, %.3f voxels): missed%s "
                       "(distance %.4f / %.4f, %.1f%% under 30 degrees)\n",
                       named.name.c_str(), grid.name.c_str(), p, shift[0], shift[1], shift[2], misses.c_str(),
                       ours.meanDistance, slicer.meanDistance, ours.below30);
        if (placements == 1)
        {
          std::snprintf(line, sizeof line, "| %s | %s | %.3f / %.3f | %zu / %zu | %.1f%% | %+.2f%% / %+.2f%% | %s | %s |\n",
                        named.name.c_str(), grid.name.c_str(), ours.meanDistance, slicer.meanDistance, ours.triangles,
                        slicer.triangles, ours.below30, ours.voxelVolumeError, slicer.voxelVolumeError,
                        ours.valid ? "yes" : "NO", misses.empty() ? "all met" : ("missed:" + misses).c_str());
          table += line;
        }
        std::fprintf(stderr, "+");
      }
      if (placements > 1)
      {
        std::string misses;
        for (const auto& [target, count] : missCounts)
          misses += (misses.empty() ? "" : ", ") + target + " " + std::to_string(count);
        std::snprintf(line, sizeof line, "| %s | %s | %d of %d | %.4f / %.4f | %.0f / %.0f | %.1f%% | %s |\n",
                      named.name.c_str(), grid.name.c_str(), metHere, placements, distance[0], distance[1],
                      triangles[0], triangles[1], below30, misses.empty() ? "none" : misses.c_str());
        table += line;
      }
    }
  if (placements == 1)
    std::snprintf(line, sizeof line, "\n%zu of %zu cases meet every target.\n", met, cases);
  else
    std::snprintf(line, sizeof line, "\n%zu of %zu cases (%d placements of each phantom on each grid) meet every target.\n",
                  met, cases, placements);
  return table + line;
}

/** The machine the figures come from: cores and processor model (from /proc/cpuinfo). */
std::string machine()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string text, model;
  int cores = 0;
  while (std::getline(cpuinfo, text))
  {
    if (text.rfind("processor", 0) == 0)
      ++cores;
    if (model.empty() && text.rfind("model name", 0) == 0)
      model = text.substr(text.find(':') + 2);
  }
  return std::to_string(cores) + " cores, " + (model.empty() ? std::string("unknown processor") : model);
}

/** Documentation/Benchmark.md: what is compared, how, the command, the machine, the tables. */
/** The hand-written notes on the targets kept from the document as it was (empty if it has none):
 *  the text from the opening marker to the closing one, both included. */
constexpr const char* targetNotesBegin = "<!-- targets notes: kept by SliceMeshBenchmark -->";
constexpr const char* targetNotesEnd = "<!-- /targets notes -->";

std::string targetNotes(const std::string& previous)
{
  const std::size_t begin = previous.find(targetNotesBegin);
  const std::size_t end = previous.find(targetNotesEnd, begin == std::string::npos ? 0 : begin);
  if (begin == std::string::npos || end == std::string::npos)
    return {};
  return previous.substr(begin, end + std::string(targetNotesEnd).size() - begin) + "\n";
}

std::string benchmarkDocument(const std::string& table, const std::string& ratios, const std::string& targets,
                              const std::string& notes, const std::string& sections)
{
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  return "# Benchmark: SliceMesh and 3D Slicer on analytic phantoms\n\n"
         "Written by the benchmark command itself; regenerate it with\n\n"
         "```sh\ncmake --build build --target SliceMeshBenchmark && ./build/Testing/Benchmark/SliceMeshBenchmark\n```\n\n"
         "Each phantom (exact signed distance known) is rasterized on two grids, and the same label map goes\n"
         "through SliceMesh (the one meshing path, `meshMask`: by default traced contours, resampled to a little\n"
         "over the target edge between thick slices, the tiling with its Steiner points, then the finishing,\n"
         "remeshed and smoothed; also the smoothed tiling only, the tiling\n"
         "as it is, and the tiling without Steiner points) and through 3D Slicer's default label map → closed\n"
         "surface conversion reproduced with VTK (pad by one voxel, vtkDiscreteFlyingEdges3D,\n"
         "vtkWindowedSincPolyDataFilter with pass band 10^(-4 × 0.5) and 20 + 40 × 0.5 iterations, boundary\n"
         "and feature-edge smoothing off, non-manifold smoothing on, normalized coordinates, in index space;\n"
         "then the image's index-to-physical mapping and vtkPolyDataNormals). Distances are from every vertex\n"
         "to the exact surface; the volume error is against the exact volume; times are wall clock.\n\n"
         "Run on " + std::string(date) + ", " + machine() + " (a shared machine: times are indicative).\n\n" +
         table + "\n" + ratios +
         "\n## The default's targets on other grids and shapes\n\n"
         "The default (remeshed) against the same Slicer pipeline on grids between and beyond the table's two\n"
         "and on shapes it does not list (branching tubes, a thin tilted plate). A case meets its targets when\n"
         "SliceMesh's mean distance and triangle count are at most Slicer's, under 1% of its triangles have an\n"
         "angle under 30°, it is valid, and its enclosed volume is at least as close to the voxels' volume as\n"
         "Slicer's. `SliceMeshBenchmark --targets` prints this table alone, and `--targets --grids\n"
         "0.6x0.6x1,1.2x1.2x2.5` the same for other grids (mm, x by y by slice); `--placements 8` puts each\n"
         "phantom at 8 places on each grid, fractions of a voxel apart, and prints the means over them.\n\n" +
         targets + (notes.empty() ? "" : "\n" + notes) +
         "\nIntermediate sections (variational implicit function) on two circles 12 mm apart, sections until the\n"
         "slab is no thicker than twice the point spacing: the fit uses at most 600 centres, so its time does\n"
         "not grow with the contours.\n\n" +
         sections;
}

} // namespace

int main(int argc, char* argv[])
{
  const char* usage = "SliceMeshBenchmark [document.md] | --targets [--grids 0.5x0.5x0.7,...] [--placements N] [--missed folder]";
  // --targets: only the default's targets on the extra grids and shapes, printed, nothing written
  // (the quick check of a change to the default); --grids picks other grids for it, --placements
  // how many places on each grid each phantom takes, --missed where the label maps of the cases that
  // miss a target are written.
  if (argc > 1 && std::string(argv[1]) == "--targets")
  {
    std::vector<BenchmarkGrid> grids = targetGrids();
    int placements = 1;
    std::string missedFolder;
    for (int i = 2; i < argc; i += 2)
    {
      const std::string option = argv[i];
      if (i + 1 >= argc || (option != "--grids" && option != "--placements" && option != "--missed"))
      {
        std::fprintf(stderr, "usage: %s\n", usage);
        return 2;
      }
      if (option == "--grids")
      {
        const auto parsed = parsedGrids(argv[i + 1]);
        if (!parsed)
        {
          std::fprintf(stderr, "SliceMeshBenchmark: --grids wants spacings such as 0.5x0.5x0.7,1x1x2.5 (mm)\n");
          return 2;
        }
        grids = *parsed;
      }
      else if (option == "--missed")
        missedFolder = argv[i + 1];
      else
      {
        char* end = nullptr;
        const long n = std::strtol(argv[i + 1], &end, 10);
        if (end == argv[i + 1] || *end != '\0' || n < 1 || n > 1000)
        {
          std::fprintf(stderr, "SliceMeshBenchmark: --placements wants a whole number from 1 to 1000\n");
          return 2;
        }
        placements = static_cast<int>(n);
      }
    }
    // Made before the meshing, so that a folder that cannot be made stops the run at once instead of
    // failing the first missed case's write minutes in.
    std::error_code made;
    if (!missedFolder.empty() && !std::filesystem::is_directory(missedFolder, made) &&
        !std::filesystem::create_directories(missedFolder, made))
    {
      std::fprintf(stderr, "SliceMeshBenchmark: cannot make the folder %s for --missed: %s\n", missedFolder.c_str(),
                   made.message().c_str());
      return 2;
    }
    std::printf("%s", targetsTable(grids, placements, missedFolder).c_str());
    return 0;
  }
  if (argc > 2 || (argc == 2 && std::string(argv[1]).rfind("--", 0) == 0))
  {
    std::fprintf(stderr, "usage: %s\n", usage);
    return 2;
  }
  const std::vector<NamedPhantom> phantoms = benchmarkPhantoms();
  const std::vector<BenchmarkGrid> grids = benchmarkGrids();

  std::vector<Row> rows;
  for (const NamedPhantom& named : phantoms)
    for (const BenchmarkGrid& grid : grids)
    {
      const GridSpec spec = gridAround(*named.phantom, grid.spacing, 2);
      const MaskVolume::Pointer mask = rasterizePhantom(*named.phantom, spec);
      // The default (finished), the smoothed tiling, the tiling, the tiling without refinement.
      const ContourPreparation byDefault = ContourPreparationOptions{}.mode;
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
  std::string ratios = "Ratio of in-plane point spacing to slice spacing (SliceMesh's default contours), which\n"
                       "dominates the angle figures of any tiling between slices:";
  for (const Row& r : rows)
    if (r.method.rfind("SliceMesh (", 0) == 0)
    {
      std::snprintf(line, sizeof line, " %s %s %.2f;", r.phantom.c_str(), r.grid.c_str(), r.spacingRatio);
      ratios += line;
    }
  ratios += "\n";

  // The implicit (RBF) intermediate sections: fit and extraction time against contour size, on two
  // circles 12 mm apart (slices far thicker than the point spacing, so the slab gets sections); the
  // fit subsamples its constraints to a fixed budget of centres.
  std::string sections = "| points per contour | sections | centres in the fit | fit (s) | extraction (s) |\n|---:|---:|---:|---:|---:|\n";
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
    std::snprintf(line, sizeof line, "| %d | %zu | %zu | %.3f | %.3f |\n", points, statistics.sectionsInserted,
                  statistics.largestFit, statistics.fitSeconds, statistics.extractSeconds);
    sections += line;
  }

  const std::string path = argc > 1 ? argv[1] : SLICEMESH_SOURCE_DIR "/Documentation/Benchmark.md";
  // Kept from the document as it was: the notes on the targets (between their markers), and the
  // scaling section (Utilities/scaling-benchmark.sh's) with what follows it (the profile).
  std::string previous;
  {
    std::ifstream in(path);
    previous.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string scaling;
  const std::size_t scalingBegin = previous.find("<!-- scaling");
  if (scalingBegin != std::string::npos)
    scaling = "\n" + previous.substr(scalingBegin);
  const std::string document =
    benchmarkDocument(table, ratios, targetsTable(targetGrids()), targetNotes(previous), sections);
  std::printf("%s", document.c_str());
  std::ofstream out(path);
  out << document << scaling;
  if (!out)
  {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return 1;
  }
  std::fprintf(stderr, "written to %s\n", path.c_str());
  return 0;
}

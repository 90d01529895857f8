// Times the finishing stage on a large mask against the tiling it finishes: a 256 x 256 x 200 grid
// holding a few large overlapping ellipsoids (an organ-sized input). Prints time per stage, triangles
// and volumes; asserts nothing (speed belongs to benchmarks). Not built by default:
//   make FinishingTiming && Testing/Reliability/FinishingTiming [sx sy sz]   (spacing in mm, 1 1 1)
#include "ContourExtraction.h"
#include "Measures/MeshQuality.h"
#include "MeshWriter.h"
#include "ReliabilitySupport.h"
#include "Finishing/SurfaceFinishing.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** Wall-clock and processor seconds of one stage: the machine may be shared, and the stages run on
 *  one thread, so the processor time is the figure to compare. */
struct Stopwatch
{
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t processor = std::clock();

  std::string lap()
  {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f s (cpu %.2f s)",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
                  static_cast<double>(std::clock() - processor) / CLOCKS_PER_SEC);
    *this = Stopwatch();
    return text;
  }
};

/** Four ellipsoids (centre and radii in voxels), two of them overlapping: one component of genus 0
 *  and two apart, tens of thousands of tiling triangles on a 1 mm grid. */
bool insideBlobs(long i, long j, long k)
{
  const double blobs[4][6] = { { 90, 100, 80, 60, 45, 55 },
                               { 140, 110, 100, 50, 40, 60 },
                               { 190, 190, 140, 40, 35, 45 },
                               { 70, 200, 150, 30, 25, 35 } };
  for (const auto& b : blobs)
  {
    const double u = (i - b[0]) / b[3], v = (j - b[1]) / b[4], w = (k - b[2]) / b[5];
    if (u * u + v * v + w * w <= 1.0)
      return true;
  }
  return false;
}

void printMesh(const char* what, const MeshValidation& v)
{
  std::printf("  %-10s %8zu triangles, %zu components, chi %ld, volume %.0f mm^3, under 30 deg %.2f%%, %s\n", what,
              v.triangles, v.components, v.eulerCharacteristic, v.volume, 100.0 * v.fractionAnglesBelow30,
              v.valid() ? "valid" : v.summary().c_str());
}

} // namespace

int main(int argc, char* argv[])
{
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  if (argc == 4)
    spacing = { std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3]) };
  const std::array<std::size_t, 3> size{ 256, 256, 200 };
  const MaskVolume::Pointer mask = makeMask(size, spacing, insideBlobs);
  std::printf("mask %zu x %zu x %zu, spacing %g x %g x %g mm\n", size[0], size[1], size[2], spacing[0], spacing[1],
              spacing[2]);

  Stopwatch watch;
  const ContourStack stack = extractContours(mask);
  const std::string extractTime = watch.lap();
  const TriangleMesh tiling = mapToPhysicalSpace(reconstructSurface(stack, {}), sliceFrameOf(mask), CoordinateSystem::LPS);
  const std::string tilingTime = watch.lap();
  const MeshValidation tilingValidation = validateMesh(tiling);
  const std::string validateTime = watch.lap();

  // The two stages on the whole mesh at once, then finishSurface itself (piece by piece, with its
  // checks and repairs), with the options the CLI uses.
  const SurfaceFinishingOptions options = finishingOptionsFor(spacing);
  watch = Stopwatch();
  TriangleMesh remeshed = remeshSurface(tiling, options.remeshing);
  const std::string remeshTime = watch.lap();
  smoothSurface(remeshed, options.smoothing);
  const std::string smoothTime = watch.lap();
  const MeshValidation remeshedValidation = validateMesh(remeshed);
  const std::string validateFinishedTime = watch.lap();
  const FinishedSurface finished = finishSurface(tiling, tilingValidation, options);
  const std::string finishTime = watch.lap();

  std::printf("  extract contours %s, tiling %s, validate tiling %s\n", extractTime.c_str(), tilingTime.c_str(),
              validateTime.c_str());
  std::printf("  remesh %s (edge %.3f mm), smooth %s, validate %s\n  finishSurface %s: %s%s%s\n", remeshTime.c_str(),
              options.remeshing.targetEdgeLength, smoothTime.c_str(), validateFinishedTime.c_str(), finishTime.c_str(),
              finishName(finished.finish), finished.fallback.empty() ? "" : ", ", finished.fallback.c_str());
  printMesh("tiling", tilingValidation);
  printMesh("remeshed", remeshedValidation);
  printMesh("finished", finished.validation);
  return 0;
}

// Property test of the finishing stage: over the property test's random label maps (blobs, noise,
// touching voxels, thin sheets and rods; isotropic, anisotropic and thick-slice spacings; oblique,
// mirrored and permuted directions) the tiling is finished at the automatic edge length of the
// mask's spacing. Whatever finish was applied, the returned mesh is valid (closed, manifold,
// oriented, no self-intersections) with the tiling's components and Euler characteristic, and
// `fallback` says why exactly when less than a remesh was applied.
//
// Printed per kind: how often each finish was applied, the fallback reasons, the share of triangles
// with an angle under 30 degrees and the triangle count finished / tiling.
// The default run finishes 12 masks per kind (the same seeds as PropertyTest.cxx); longer:
// SLICEMESH_PROPERTY_CASES=2000 ctest -R FinishingProperty ; one seed: SLICEMESH_PROPERTY_SEED=123.
#include "PropertySeeds.h"
#include "ReliabilitySupport.h"
#include "SurfaceFinishing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

namespace slicemesh::testing
{
namespace
{

/** A short name for why one stage's surface was not kept: "threw", "topology", "open",
 *  "non-manifold", "self-intersecting", else "other". */
std::string reasonClass(const std::string& why)
{
  if (why.find("topology changed") != std::string::npos)
    return "topology";
  if (why.find("triangles,") == std::string::npos)
    return "threw"; // not a validation summary: the error remeshSurface or smoothSurface threw
  if (why.find("open (") != std::string::npos)
    return "open";
  if (why.find("non-manifold") != std::string::npos)
    return "non-manifold";
  if (why.find("self-intersecting") != std::string::npos)
    return "self-intersecting";
  return "other"; // degenerate triangles or an inverted orientation: the summary does not name them
}

/** The fallback text reduced to its reasons, e.g. "remesh: self-intersecting; smooth: topology". */
std::string fallbackClass(const std::string& fallback)
{
  const std::string remeshed = "the remeshed surface was not kept: ", smoothed = "the smoothed surface was not kept: ";
  std::string result;
  const std::size_t r = fallback.find(remeshed), s = fallback.find(smoothed);
  if (r != std::string::npos)
    result = "remesh: " + reasonClass(fallback.substr(r + remeshed.size(), s == std::string::npos ? s : s - r - remeshed.size()));
  if (s != std::string::npos)
    result += (result.empty() ? "" : "; ") + std::string("smooth: ") + reasonClass(fallback.substr(s + smoothed.size()));
  return result.empty() ? fallback : result;
}

struct Figures
{
  std::size_t finished = 0, skipped = 0, failures = 0;
  std::map<SurfaceFinish, std::size_t> applied;
  std::map<std::string, std::size_t> reasons;
  std::map<std::string, std::string> firstSeedOfReason;
  double tilingTriangles = 0.0, finishedTriangles = 0.0;
  double tilingBelow30 = 0.0, finishedBelow30 = 0.0; ///< triangles with an angle under 30 degrees
  double minRatio = 1e300, maxRatio = 0.0;           ///< finished / tiling triangles, one mask
};

void print(const char* kind, const Figures& f)
{
  std::ostringstream out;
  out << "[ finishing ] " << kind << ": " << f.finished << " masks finished (" << f.skipped
      << " empty or without a valid tiling), " << f.failures << " failures; applied";
  for (const auto& [finish, count] : f.applied)
    out << " " << finishName(finish) << " " << count;
  char figures[256];
  std::snprintf(figures, sizeof figures,
                "; under 30 deg %.2f%% -> %.2f%% of triangles; triangles finished / tiling %.3f (per mask %.3f .. %.3f)",
                100.0 * f.tilingBelow30 / std::max(1.0, f.tilingTriangles),
                100.0 * f.finishedBelow30 / std::max(1.0, f.finishedTriangles),
                f.finishedTriangles / std::max(1.0, f.tilingTriangles), f.finished ? f.minRatio : 0.0, f.maxRatio);
  out << figures << "\n";
  for (const auto& [reason, count] : f.reasons)
    out << "[ finishing ]   fallback " << count << "x: " << reason << " (first: " << f.firstSeedOfReason.at(reason) << ")\n";
  std::cout << out.str() << std::flush;
}

void runFinishingProperty(RandomMaskKind kind, const char* kindName, std::uint64_t firstSeed)
{
  const auto [begin, end] = propertySeeds(firstSeed, 12);
  Figures figures;
  std::ostringstream failures;
  for (std::uint64_t seed = begin; seed < end; ++seed)
  {
    const RandomMask random = randomMask(seed, kind);
    const MaskMeshResult tiling = meshMask(random.mask);
    if (tiling.contours == 0 || !tiling.error.empty())
    {
      ++figures.skipped; // nothing to finish
      continue;
    }
    const auto spacing = random.mask->GetSpacing();
    SurfaceFinishingOptions options;
    options.remeshing.targetEdgeLength = automaticEdgeLength({ spacing[0], spacing[1], spacing[2] });
    const FinishedSurface finished = finishSurface(tiling.mesh, tiling.validation, options);
    if (!tiling.validation.valid())
    { // PropertyTest's failure to report; finishing only has to hand such a tiling back, and say so
      ++figures.skipped;
      if (finished.finish != SurfaceFinish::Tiled || finished.fallback.empty() ||
          finished.mesh.triangles != tiling.mesh.triangles)
      {
        ++figures.failures;
        failures << random.description << ": an invalid tiling was finished (" << finishName(finished.finish) << ")\n";
      }
      continue;
    }
    ++figures.finished;
    ++figures.applied[finished.finish];

    // The validation handed back is checked again on the mesh itself.
    const MeshValidation v = validateMesh(finished.mesh);
    std::string problem;
    if (!v.valid())
      problem = "invalid finished mesh: " + v.summary();
    else if (v.components != tiling.validation.components || v.eulerCharacteristic != tiling.validation.eulerCharacteristic)
      problem = "topology changed: " + std::to_string(v.components) + " components, chi " +
                std::to_string(v.eulerCharacteristic) + " instead of " + std::to_string(tiling.validation.components) +
                ", " + std::to_string(tiling.validation.eulerCharacteristic);
    else if (v.triangles != finished.validation.triangles || v.volume != finished.validation.volume)
      problem = "the returned validation is not the mesh's";
    else if (finished.fallback.empty() != (finished.finish == SurfaceFinish::Remeshed))
      problem = std::string(finishName(finished.finish)) + " applied, fallback \"" + finished.fallback + "\"";
    if (!problem.empty())
    {
      ++figures.failures;
      failures << random.description << ": " << problem << "\n";
    }

    if (!finished.fallback.empty())
    {
      const std::string reason = fallbackClass(finished.fallback);
      if (figures.reasons[reason]++ == 0)
        figures.firstSeedOfReason[reason] = "seed " + std::to_string(seed) + ": " + finished.fallback;
    }
    const double before = static_cast<double>(tiling.validation.triangles), after = static_cast<double>(v.triangles);
    figures.tilingTriangles += before;
    figures.finishedTriangles += after;
    figures.tilingBelow30 += tiling.validation.fractionAnglesBelow30 * before;
    figures.finishedBelow30 += v.fractionAnglesBelow30 * after;
    figures.minRatio = std::min(figures.minRatio, after / before);
    figures.maxRatio = std::max(figures.maxRatio, after / before);
  }
  print(kindName, figures);
  EXPECT_EQ(figures.failures, 0u) << failures.str();
}

TEST(FinishingProperty, RandomBlobsFinishToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::Blobs, "blobs", 1000);
}
TEST(FinishingProperty, RandomNoiseFinishesToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::Noise, "noise", 2000);
}
TEST(FinishingProperty, BlobsWithNoiseFinishToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::BlobsAndNoise, "blobs+noise", 3000);
}
TEST(FinishingProperty, EdgeAndCornerTouchingVoxelsFinishToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::Touching, "touching", 4000);
}
TEST(FinishingProperty, ThinSheetsAndRodsFinishToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::Thin, "thin", 5000);
}

} // namespace
} // namespace slicemesh::testing

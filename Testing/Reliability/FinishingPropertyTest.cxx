// Property test of the finishing stage: over the property test's random label maps (blobs, noise,
// touching voxels, thin sheets and rods; isotropic, anisotropic and thick-slice spacings; oblique,
// mirrored and permuted directions) the tiling is finished as the CLI finishes it
// (finishingOptionsFor the mask's spacing). Whatever finish was applied, the returned mesh is
// valid (closed, manifold, oriented, no self-intersections) with the tiling's components and Euler
// characteristic, its volume is within PropertyTest's tolerance of the mask's voxel volume, and
// `fallback` says why exactly when less than a remesh was applied.
//
// Printed per kind and finish applied: how often, the share of triangles with an angle under 30
// degrees, the triangle count and volume finished / tiling; and the fallback reasons.
// The default run finishes 12 masks per kind (the same seeds as PropertyTest.cxx); longer:
// SLICEMESH_PROPERTY_CASES=2000 ctest -R FinishingProperty ; one seed: SLICEMESH_PROPERTY_SEED=123.
#include "ContourExtraction.h"
#include "PropertySeeds.h"
#include "ReliabilitySupport.h"
#include "Finishing/SurfaceFinishing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace slicemesh::testing
{
namespace
{

/** Seeds whose finished mesh was valid but blown up at 920d25d (a few-voxel component collapsed
 *  under Taubin's filter and the volume restoration threw it 1e12 mm and more out): 3002, 4000,
 *  4005, 4006, 5002, 5009; they pass since 2d099ce. Counted, not failed, unless
 *  SLICEMESH_PROPERTY_STRICT is set; a listed seed that passes is named. */
const std::uint64_t knownVolumeFailures[] = { 0 }; // 0 is a placeholder, never a seed here

bool isKnownVolumeFailure(std::uint64_t seed)
{
  return !strictPropertyRun() &&
         std::find(std::begin(knownVolumeFailures), std::end(knownVolumeFailures), seed) != std::end(knownVolumeFailures);
}

/** Seeds on which remeshSurface crashed: 3369 (blobs+noise) at 7ddd116, a SIGSEGV in CGAL 5.5's
 *  tangential relaxation, whose check_normals reads the edge of a null halfedge when every face
 *  around a vertex is degenerate (CGAL issue 7345); it passes since 4a3b583 leaves specks under 100
 *  tiling triangles as tiled. Skipped unless SLICEMESH_PROPERTY_STRICT is set, so a long run ends. */
const std::uint64_t knownCrashes[] = { 0 }; // 0 is a placeholder, never a seed here

bool isKnownCrash(std::uint64_t seed)
{
  return !strictPropertyRun() && std::find(std::begin(knownCrashes), std::end(knownCrashes), seed) != std::end(knownCrashes);
}

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

/** The fallback text reduced to its reasons, e.g. "remesh: self-intersecting; smooth: topology", or
 *  for a piece-by-piece finish "pieces: crossed another piece" (the first piece's reason). */
std::string fallbackClass(const std::string& fallback)
{
  if (fallback.find("pieces were finished less than asked") != std::string::npos)
  {
    const std::size_t first = fallback.find("the first: ");
    const std::string why = first == std::string::npos ? fallback : fallback.substr(first + 11);
    if (why.find("crossed another piece") != std::string::npos)
      return "pieces: crossed another piece";
    return "pieces: " + (why.find("triangles,") == std::string::npos ? why.substr(0, 60) : reasonClass(why));
  }
  const std::string remeshed = "the remeshed surface was not kept: ", smoothed = "the smoothed surface was not kept: ";
  std::string result;
  const std::size_t r = fallback.find(remeshed), s = fallback.find(smoothed);
  if (r != std::string::npos)
    result = "remesh: " + reasonClass(fallback.substr(r + remeshed.size(), s == std::string::npos ? s : s - r - remeshed.size()));
  if (s != std::string::npos)
    result += (result.empty() ? "" : "; ") + std::string("smooth: ") + reasonClass(fallback.substr(s + smoothed.size()));
  return result.empty() ? fallback : result;
}

/** What the masks given one finish look like, before and after. */
struct FinishFigures
{
  std::size_t masks = 0;
  double tilingTriangles = 0.0, finishedTriangles = 0.0;
  double tilingBelow30 = 0.0, finishedBelow30 = 0.0;   ///< triangles with an angle under 30 degrees
  double minRatio = 1e300, maxRatio = 0.0;             ///< finished / tiling triangles, one mask
  double minVolumeRatio = 1e300, maxVolumeRatio = 0.0; ///< finished / tiling volume, one mask
  std::size_t outsideVolumeTolerance = 0; ///< finished volume off the voxels' by more than PropertyTest allows

  void add(const MaskMeshResult& run, const MeshValidation& finished)
  {
    ++masks;
    const MeshValidation& tiling = run.meshing.tilingValidation;
    const double before = static_cast<double>(tiling.triangles);
    const double after = static_cast<double>(finished.triangles);
    tilingTriangles += before;
    finishedTriangles += after;
    tilingBelow30 += tiling.fractionAnglesBelow30 * before;
    finishedBelow30 += finished.fractionAnglesBelow30 * after;
    minRatio = std::min(minRatio, after / before);
    maxRatio = std::max(maxRatio, after / before);
    const double volumeRatio = finished.volume / tiling.volume;
    minVolumeRatio = std::min(minVolumeRatio, volumeRatio);
    maxVolumeRatio = std::max(maxVolumeRatio, volumeRatio);
    if (std::abs(finished.volume - run.voxelVolume) > run.volumeTolerance())
      ++outsideVolumeTolerance;
  }
};

struct Figures
{
  std::size_t finished = 0, skipped = 0, failures = 0, knownFailures = 0;
  std::map<SurfaceFinish, FinishFigures> applied;
  std::map<std::string, std::size_t> reasons;
  std::map<std::string, std::string> firstSeedOfReason;
};

void print(const char* kind, const Figures& f)
{
  std::ostringstream out;
  out << "[ finishing ] " << kind << ": " << f.finished << " masks finished (" << f.skipped
      << " empty or without a valid tiling), " << f.failures << " failures, " << f.knownFailures
      << " known volume failures or crashes\n";
  for (const auto& [finish, a] : f.applied)
  {
    char line[400];
    std::snprintf(line, sizeof line,
                  "[ finishing ]   %-8s %4zu: under 30 deg %5.2f%% -> %5.2f%% of triangles; triangles finished / tiling "
                  "%.3f (per mask %.3f .. %.3f); volume finished / tiling %.3f .. %.3f, %zu off the voxels' by more "
                  "than PropertyTest's tolerance\n",
                  finishName(finish), a.masks, 100.0 * a.tilingBelow30 / std::max(1.0, a.tilingTriangles),
                  100.0 * a.finishedBelow30 / std::max(1.0, a.finishedTriangles),
                  a.finishedTriangles / std::max(1.0, a.tilingTriangles), a.minRatio, a.maxRatio, a.minVolumeRatio,
                  a.maxVolumeRatio, a.outsideVolumeTolerance);
    out << line;
  }
  for (const auto& [reason, count] : f.reasons)
    out << "[ finishing ]   fallback " << count << "x: " << reason << " (first: " << f.firstSeedOfReason.at(reason) << ")\n";
  std::cout << out.str() << std::flush;
}

void runFinishingProperty(RandomMaskKind kind, const char* kindName, std::uint64_t firstSeed, std::uint64_t defaultCases = 12)
{
  const auto [begin, end] = propertySeeds(firstSeed, defaultCases);
  Figures figures;
  std::ostringstream failures;
  for (std::uint64_t seed = begin; seed < end; ++seed)
  {
    if (isKnownCrash(seed))
    {
      ++figures.knownFailures;
      continue;
    }
    const RandomMask random = randomMask(seed, kind);
    // The one meshing path as the CLI runs it by default (finishing at the grid's automatic values).
    MeshingOptions meshing;
    meshing.reconstruction = random.options;
    const MaskMeshResult run = checkedMesh(random.mask, meshing);
    if (run.contours == 0 || !run.error.empty())
    {
      ++figures.skipped; // nothing to finish
      continue;
    }
    // The pipeline leaves a finished tiling's self-intersection test to the finishing: tested here.
    const MeshValidation tiled = validateMesh(run.meshing.tiling);
    const FinishedSurface& finished = run.meshing.surface;
    if (!tiled.valid())
    { // PropertyTest's failure to report. Finishing hands back a tiling that is no sound surface, and
      // says so; one that only crosses itself it may finish, into a valid surface.
      ++figures.skipped;
      const bool handedBack = finished.finish == SurfaceFinish::Tiled && !finished.fallback.empty() &&
                              finished.mesh.triangles == run.meshing.tiling.triangles;
      if (!handedBack && !(tiled.soundTopology() && validateMesh(finished.mesh).valid()))
      {
        ++figures.failures;
        failures << random.description << ": an invalid tiling was finished (" << finishName(finished.finish) << ")\n";
      }
      continue;
    }
    ++figures.finished;

    // The validation handed back is checked again on the mesh itself.
    const MeshValidation v = validateMesh(finished.mesh);
    std::string problem;
    if (!v.valid())
      problem = "invalid finished mesh: " + v.summary();
    else if (v.components != tiled.components || v.eulerCharacteristic != tiled.eulerCharacteristic)
      problem = "topology changed: " + std::to_string(v.components) + " components, chi " +
                std::to_string(v.eulerCharacteristic) + " instead of " + std::to_string(tiled.components) +
                ", " + std::to_string(tiled.eulerCharacteristic);
    // The returned validation is put together piece by piece: the same counts, the volume summed in
    // another order (equal to rounding).
    else if (v.triangles != finished.validation.triangles || v.components != finished.validation.components ||
             v.eulerCharacteristic != finished.validation.eulerCharacteristic ||
             v.selfIntersections != finished.validation.selfIntersections ||
             std::abs(v.volume - finished.validation.volume) > 1e-9 * std::abs(v.volume))
      problem = "the returned validation is not the mesh's";
    else if (finished.fallback.empty() != (finished.finish == SurfaceFinish::Remeshed))
      problem = std::string(finishName(finished.finish)) + " applied, fallback \"" + finished.fallback + "\"";
    else if (std::abs(v.volume - run.voxelVolume) > run.volumeTolerance())
    {
      if (isKnownVolumeFailure(seed))
        ++figures.knownFailures;
      else
        problem = std::string(finishName(finished.finish)) + " volume " + std::to_string(v.volume) + " mm^3, voxels " +
                  std::to_string(run.voxelVolume) + " mm^3, tolerance " + std::to_string(run.volumeTolerance());
    }
    else if (isKnownVolumeFailure(seed))
      std::cout << "[ finishing ] known-failing seed " << seed << " passes now: remove it from knownVolumeFailures\n";
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
    figures.applied[finished.finish].add(run, v);
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
TEST(FinishingProperty, ThresholdedMriFinishesToValidSurfacesOfTheSameTopology)
{
  runFinishingProperty(RandomMaskKind::ThresholdedMri, "thresholded MRI", 6000, 24);
}

} // namespace
} // namespace slicemesh::testing

namespace slicemesh::testing
{

TEST(FinishingProperty, Seed3369TheMaskThatCrashedCGALsRelaxation)
{
  // Twelve voxels (seed 3369 of blobs+noise, minimized): CGAL 5.5.1's tangential relaxation, inside
  // the isotropic remeshing, read a null halfedge where every face around a vertex had become
  // degenerate (CGAL issue 7345) and the process died. Pieces this small now stay as tiled; the
  // stage must come back with a valid surface of the tiling's topology.
  const MaskVolume::Pointer mask = makeMask({ 8, 10, 14 }, { 1.0, 1.0, 1.0 });
  for (const auto& [i, j, k] : std::vector<std::array<long, 3>>{ { 1, 1, 1 }, { 3, 1, 1 }, { 5, 2, 1 }, { 2, 6, 1 },
                                                                  { 0, 0, 2 }, { 0, 3, 2 }, { 4, 3, 2 }, { 2, 4, 2 },
                                                                  { 2, 5, 2 }, { 2, 6, 2 }, { 2, 7, 2 }, { 4, 3, 3 } })
    mask->SetPixel({ { i, j, k } }, 1);
  const TriangleMesh tiling = reconstructSurface(extractContours(mask));
  const MeshValidation tiled = validateMesh(tiling);
  ASSERT_TRUE(tiled.valid()) << tiled.summary();
  const FinishedSurface finished = finishSurface(tiling, tiled, finishingOptionsFor({ 1.0, 1.0, 1.0 }));
  EXPECT_TRUE(finished.validation.valid()) << finished.validation.summary();
  EXPECT_EQ(finished.validation.components, tiled.components);
  EXPECT_EQ(finished.validation.eulerCharacteristic, tiled.eulerCharacteristic);

  // The remeshing itself, on every piece of it however small, is where the process died: it must
  // come back with a closed surface (its relaxation step refuses moves it cannot judge).
  const TriangleMesh remeshed = remeshSurface(tiling, finishingOptionsFor({ 1.0, 1.0, 1.0 }).remeshing);
  const MeshValidation remeshedValidation = validateMesh(remeshed);
  EXPECT_TRUE(remeshedValidation.closed()) << remeshedValidation.summary();
  EXPECT_EQ(remeshedValidation.components, tiled.components);
}

} // namespace slicemesh::testing

namespace slicemesh::testing
{

/** The random mask of this seed and kind meshed with its own options; expects it remeshed, as
 *  asked, into a valid surface of its tiled topology with the voxels' volume. */
FinishedSurface expectRemeshedToItsTiledTopology(std::uint64_t seed, RandomMaskKind kind)
{
  const RandomMask random = randomMask(seed, kind);
  MeshingOptions meshing;
  meshing.reconstruction = random.options;
  const MaskMeshResult run = checkedMesh(random.mask, meshing);
  if (!run.error.empty())
  {
    ADD_FAILURE() << run.error;
    return {};
  }
  const FinishedSurface& finished = run.meshing.surface;
  const MeshValidation tiled = validateMesh(run.meshing.tiling);
  const MeshValidation v = validateMesh(finished.mesh);
  EXPECT_EQ(finished.finish, SurfaceFinish::Remeshed) << finished.fallback;
  EXPECT_TRUE(finished.fallback.empty()) << finished.fallback;
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, tiled.components);
  EXPECT_EQ(v.eulerCharacteristic, tiled.eulerCharacteristic);
  EXPECT_NEAR(v.volume, run.voxelVolume, run.volumeTolerance());
  return finished;
}

TEST(FinishingProperty, ARemeshThatCrossesItselfIsRemeshedAgainAroundTheCrossings)
{
  // Random noise (seed 2010 of the property test): a piece with sheets closer than the target edge,
  // where the remesh's chords pass through the other sheet in more places than flips and collapses
  // undo. Before, that piece was then smoothed only or kept as tiled; now it is remeshed again with
  // the tiled triangles around the crossings kept (1957 of 7412 here), and counts as remeshed.
  const FinishedSurface finished = expectRemeshedToItsTiledTopology(2010, RandomMaskKind::Noise);
  EXPECT_GT(finished.trianglesKeptTiled, 0u);
  EXPECT_LT(2 * finished.trianglesKeptTiled, finished.mesh.triangles.size());
}

TEST(FinishingProperty, AFewFoldsOfTheRemeshAreUndoneWhereTheyAre)
{
  // Voxels that touch only along an edge (seed 4001) and noise beside blobs (seed 3165): the remesh
  // folds over itself in one or two places that smoothing did not cause. Those folds are flipped or
  // collapsed away where they are: the piece is not remeshed again around them (no tiled triangle
  // kept; before, 400 were for seed 4001). (Seed 3010 folded so until its random spacing was
  // rounded to six digits for the meshing; where a remesh folds depends on such details.)
  for (const auto& [seed, kind] :
       { std::pair{ 4001u, RandomMaskKind::Touching }, std::pair{ 3165u, RandomMaskKind::BlobsAndNoise } })
  {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const FinishedSurface finished = expectRemeshedToItsTiledTopology(seed, kind);
    EXPECT_GT(finished.crossingRepairOperations, 0u);
    EXPECT_EQ(finished.trianglesKeptTiled, 0u);
  }
}

} // namespace slicemesh::testing

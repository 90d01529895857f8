// Property test: over many seeded random label maps (blobs, noise, edge/corner-touching voxels,
// one-slice sheets; isotropic, anisotropic and thick-slice spacings; identity, oblique, mirrored and
// permuted directions) every mesh is closed, 2-manifold, consistently and outward oriented,
// free of degenerate triangles and self-intersections, and its volume is within the stated
// tolerance of the mask's voxel volume (MaskMeshResult::volumeTolerance).
//
// The default run meshes SLICEMESH_PROPERTY_CASES (default 80) masks per kind, 400 in all.
// Longer: SLICEMESH_PROPERTY_CASES=2000 ctest -R Property ; one seed: SLICEMESH_PROPERTY_SEED=123
// (with the kind's test filter). A failing seed is printed with a reproducer to paste.
#include "PropertySeeds.h"
#include "ReliabilitySupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace slicemesh::testing
{
namespace
{

/** Seeds on which the Logic is known to fail: meshed and reported, but they do not fail the default
 *  run (SLICEMESH_PROPERTY_STRICT=1 counts them); a seed that passes again is named by the run.
 *  None today: the seeds listed before (2060, 3048) and those a 5000-mask run found (2511, 2651)
 *  pass, with regression tests in KnownLogicFailuresTest.cxx and Testing/Logic/DeterminismTest.cxx
 *  (3048 passed or failed from run to run while the tiling followed CGAL's address-ordered edges). */
const std::uint64_t knownLogicFailures[] = { 0 }; // 0 is a placeholder, never a seed here
/** Seeds on which reconstructSurface did not return (over 20 s on a 16^3 mask) at 25f8b8a; they pass
 *  at 24484fa. Skipped unless SLICEMESH_PROPERTY_STRICT=1; 0 is a placeholder, never a seed here. */
const std::uint64_t knownLogicHangs[] = { 0 };

template <std::size_t N>
bool listed(const std::uint64_t (&seeds)[N], std::uint64_t seed)
{
  return !strictPropertyRun() && std::find(std::begin(seeds), std::end(seeds), seed) != std::end(seeds);
}

bool isKnownFailure(std::uint64_t seed)
{
  return listed(knownLogicFailures, seed);
}

struct Figures
{
  std::size_t cases = 0, empty = 0, failures = 0, knownFailures = 0;
  std::size_t folded = 0; ///< valid meshes with a folded edge (reported, not a failure: see MeshValidation)
  double worstVolumeRatio = 0.0; ///< |volume - voxel volume| / tolerance, largest seen
};

void runProperty(RandomMaskKind kind, std::uint64_t firstSeed, std::uint64_t defaultCases = 80)
{
  const auto [begin, end] = propertySeeds(firstSeed, defaultCases);
  Figures figures;
  std::ostringstream failures;
  for (std::uint64_t seed = begin; seed < end; ++seed)
  {
    const RandomMask random = randomMask(seed, kind);
    ++figures.cases;
    if (listed(knownLogicHangs, seed))
    {
      ++figures.knownFailures;
      continue;
    }
    const MaskMeshResult result = checkedMesh(random.mask, random.options);
    if (result.contours == 0)
    {
      ++figures.empty; // nothing to mesh: reconstructSurface is expected to say so
      if (result.error.empty() && !result.mesh.triangles.empty())
        failures << random.description << ": an empty mask gave a mesh\n";
      continue;
    }
    const std::string problem = result.problem();
    if (problem.empty() && result.validation.foldedEdges > 0)
      ++figures.folded;
    if (result.error.empty() && result.volumeTolerance() > 0.0)
      figures.worstVolumeRatio = std::max(figures.worstVolumeRatio, std::abs(result.validation.volume - result.voxelVolume) /
                                                                      result.volumeTolerance());
    if (isKnownFailure(seed))
    {
      if (problem.empty())
        std::cout << "[ property ] known-failing seed " << seed << " passes now: remove it from knownLogicFailures\n";
      else
        ++figures.knownFailures;
      continue;
    }
    if (!problem.empty())
    {
      ++figures.failures;
      if (figures.failures <= 5)
        failures << random.description << ": " << problem << "\n" << maskAsCode(random.mask) << "\n";
      else
        failures << random.description << ": " << problem << "\n";
    }
  }
  std::cout << "[ property ] " << figures.cases << " masks (" << figures.empty << " empty), " << figures.failures
            << " failures, " << figures.knownFailures << " known Logic failures, " << figures.folded
            << " valid but with a folded edge; worst |volume - voxel volume| / tolerance = " << figures.worstVolumeRatio << std::endl;
  EXPECT_EQ(figures.failures, 0u) << failures.str();
}

TEST(Property, RandomBlobsGiveValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::Blobs, 1000); }
TEST(Property, RandomNoiseGivesValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::Noise, 2000); }
TEST(Property, BlobsWithNoiseGiveValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::BlobsAndNoise, 3000); }
TEST(Property, EdgeAndCornerTouchingVoxelsGiveValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::Touching, 4000); }
TEST(Property, ThinSheetsAndRodsGiveValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::Thin, 5000); }
TEST(Property, ThresholdedMriGivesValidMeshesOfTheRightVolume) { runProperty(RandomMaskKind::ThresholdedMri, 6000, 24); }

} // namespace
} // namespace slicemesh::testing

// Specks through the one meshing path, finished as the CLI finishes them: pieces of a few voxels,
// under 48 triangles of the target edge in area, which a remesh at that edge would collapse. Each
// is remeshed at its own scale (about as many triangles as its tiling), smoothed and given its
// volume back: asserted valid, of its tiled topology, well shaped, with the volume it had as tiled
// (the traced contours at the 0.5 level cut a small piece's corners: a one-voxel speck's tiling
// holds about half its voxel, and keeps it).
#include "ReliabilitySupport.h"
#include "Measures/MeshQuality.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

namespace slicemesh::testing
{
namespace
{

struct Speck
{
  const char* name;
  std::array<std::size_t, 3> size;
  std::array<double, 3> spacing;
  std::function<bool(long, long, long)> inside;
};

bool everywhere(long, long, long)
{
  return true;
}

/** The specks of the tests: a voxel, bars one voxel thin along and across the slices and an L, on
 *  1 mm voxels and on 0.5 x 0.5 x 2 mm ones (thick slices), and a 2x2x3 blob of 1 mm voxels (of the
 *  thin voxels it is no speck). The mask is padded by a voxel. */
std::vector<Speck> specks()
{
  auto padded = [](std::array<std::size_t, 3> size, std::function<bool(long, long, long)> inside)
  {
    return std::make_pair(std::array<std::size_t, 3>{ size[0] + 2, size[1] + 2, size[2] + 2 },
                          [=](long i, long j, long k)
                          {
                            return i >= 1 && j >= 1 && k >= 1 && i <= static_cast<long>(size[0]) &&
                                   j <= static_cast<long>(size[1]) && k <= static_cast<long>(size[2]) &&
                                   inside(i - 1, j - 1, k - 1);
                          });
  };
  std::vector<Speck> all;
  auto add = [&](const char* name, std::array<std::size_t, 3> size, std::array<double, 3> spacing,
                 std::function<bool(long, long, long)> inside)
  {
    auto [paddedSize, paddedInside] = padded(size, std::move(inside));
    all.push_back({ name, paddedSize, spacing, paddedInside });
  };
  for (const std::array<double, 3> spacing : { std::array<double, 3>{ 1.0, 1.0, 1.0 }, std::array<double, 3>{ 0.5, 0.5, 2.0 } })
  {
    add("one voxel", { 1, 1, 1 }, spacing, everywhere);
    if (spacing[2] == 1.0)
      add("2x2x3 blob", { 2, 2, 3 }, spacing, everywhere);
    add("bar 4 voxels long, 1 thin, in the slice", { 4, 1, 1 }, spacing, everywhere);
    add("bar 3 voxels long, 1 thin, across the slices", { 1, 1, 3 }, spacing, everywhere);
    add("L of 5 voxels", { 3, 3, 1 }, spacing, [](long i, long j, long) { return i == 0 || j == 0; });
  }
  return all;
}

TEST(SpeckFinishing, ASpeckIsRemeshedAtItsOwnScaleValidWellShapedAndWithItsVolume)
{
  for (const Speck& speck : specks())
  {
    const MaskMeshResult result = checkedMesh(makeMask(speck.size, speck.spacing, speck.inside).GetPointer(), MeshingOptions{});
    const std::string name = std::string(speck.name) + " on " + std::to_string(speck.spacing[0]) + " x " +
                             std::to_string(speck.spacing[2]) + " mm voxels";
    ASSERT_TRUE(result.error.empty()) << name << ": " << result.error;
    const FinishedSurface& finished = result.meshing.surface;
    const MeshValidation& tiled = result.meshing.tilingValidation;
    const MeshQuality tiledQuality = measureMeshQuality(result.meshing.tiling);
    const MeshQuality quality = measureMeshQuality(finished.mesh);
    std::printf("%s: %.2f mm^3 of voxels; tiled %zu triangles, %.0f%% under 30 deg (smallest %.1f), %.3f mm^3; "
                "finished %zu triangles, %.0f%% under 30 deg (smallest %.1f), %.3f mm^3\n",
                name.c_str(), result.voxelVolume, result.meshing.tiling.triangles.size(),
                100.0 * tiledQuality.fractionBelow30, tiledQuality.minAngleDegrees, tiled.volume,
                finished.mesh.triangles.size(), 100.0 * quality.fractionBelow30, quality.minAngleDegrees,
                result.validation.volume);
    EXPECT_EQ(finished.smallPiecesRemeshed, 1u) << name;
    EXPECT_EQ(finished.smallPiecesAsTiled, 0u) << name;
    EXPECT_EQ(finished.finish, SurfaceFinish::Remeshed) << name;
    EXPECT_TRUE(finished.fallback.empty()) << name << ": " << finished.fallback;
    // Valid, of the tiling's topology, facing out: checked anew on the mesh as written.
    EXPECT_TRUE(result.validation.valid()) << name << ": " << result.validation.summary();
    EXPECT_EQ(result.validation.components, 1u) << name;
    EXPECT_EQ(result.validation.eulerCharacteristic, 2) << name;
    EXPECT_GT(result.validation.volume, 0.0) << name;
    // Where the voxels are: within the reliability tests' tolerance of the voxels' volume.
    EXPECT_TRUE(result.volumeWithinTolerance()) << name << ": " << result.problem();
    // Given its volume back as far as half again its tiled volume (a voxel is tiled at a sixth of
    // its own), within 3%: the offset's steps, and a speck's target is its contours' share.
    EXPECT_GE(result.validation.volume, 0.97 * std::min(result.voxelVolume, 1.5 * tiled.volume)) << name;
    // Well shaped, with about as many triangles as tiled. A voxel four times as long as it is wide
    // leaves a few triangles of its ends under 30 degrees (2 of 24; as tiled, 4 of 28).
    EXPECT_LE(quality.fractionBelow30, 0.1) << name;
    EXPECT_LE(quality.fractionBelow30, tiledQuality.fractionBelow30 + 1e-9) << name;
    EXPECT_LE(finished.mesh.triangles.size(), 2 * result.meshing.tiling.triangles.size()) << name;
  }
}

bool samePoints(const std::vector<Point3>& a, const std::vector<Point3>& b)
{
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Point3& p, const Point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; });
}

TEST(SpeckFinishing, SpecksBesideABlockStayApartAndTheSameOnOneTwoAndEightThreads)
{
  // A block of 8x8x6 voxels and, around it, single voxels and pairs touching it or each other only
  // at an edge or a corner (separate pieces of the tiling, their surfaces a fraction of a voxel
  // apart): the specks finished beside each other and the block must not cross them (a speck that
  // does goes back to its tiled shape), and the result is the same bit for bit on any number of
  // threads.
  const auto inside = [](long i, long j, long k)
  {
    const bool block = i >= 4 && i < 12 && j >= 4 && j < 12 && k >= 1 && k < 7;
    const bool diagonal = (i + j) % 2 == 0 && (i == 3 || i == 12 || j == 3 || j == 12) && k % 2 == 1 && k < 8;
    const bool beyond = i == 1 && j % 3 == 0 && k == 3;
    return block || diagonal || beyond;
  };
  MeshingOptions options;
  options.threads = 1;
  const MaskMeshResult onOne = checkedMesh(makeMask({ 16, 16, 9 }, { 1.0, 1.0, 1.0 }, inside).GetPointer(), options);
  ASSERT_TRUE(onOne.error.empty()) << onOne.error;
  const FinishedSurface& finished = onOne.meshing.surface;
  std::printf("%zu pieces: %zu specks remeshed, %zu left as tiled; %s\n", onOne.validation.components,
              finished.smallPiecesRemeshed, finished.smallPiecesAsTiled, onOne.validation.summary().c_str());
  EXPECT_TRUE(onOne.validation.valid()) << onOne.validation.summary();
  EXPECT_EQ(onOne.validation.components, onOne.meshing.tilingValidation.components);
  EXPECT_EQ(onOne.validation.eulerCharacteristic, onOne.meshing.tilingValidation.eulerCharacteristic);
  EXPECT_TRUE(finished.fallback.empty()) << finished.fallback;
  EXPECT_GT(finished.smallPiecesRemeshed, 20u);
  EXPECT_EQ(finished.smallPiecesRemeshed + finished.smallPiecesAsTiled + 1, onOne.validation.components);
  for (unsigned int threads : { 2u, 8u })
  {
    options.threads = threads;
    const MaskMeshResult more = checkedMesh(makeMask({ 16, 16, 9 }, { 1.0, 1.0, 1.0 }, inside).GetPointer(), options);
    EXPECT_EQ(more.mesh.triangles, onOne.mesh.triangles) << threads << " threads";
    EXPECT_TRUE(samePoints(more.mesh.points, onOne.mesh.points)) << threads << " threads";
  }
}

} // namespace
} // namespace slicemesh::testing

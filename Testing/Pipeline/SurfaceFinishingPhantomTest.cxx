// The finishing stage (3D smoothing and isotropic remeshing after the tiling) on analytic phantoms,
// on the grids of PhantomMeshTest: the surface gets closer to the exact one than the tiling, with
// fewer triangles than flying edges makes on the same grid and under 1% of them with an angle under
// 30 degrees; and it stays a valid surface of the tiling's topology, thin tubes included.
#include "Box.h"
#include "CappedCylinder.h"
#include "PhantomMeshing.h"
#include "Sphere.h"
#include "Core/AreaNormal.h"
#include "Finishing/SurfaceFinishing.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "MaskMeshing.h"
#include "PhantomGrid.h"
#include "Torus.h"
#include "TubeTree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

double meanDistance(const Phantom& phantom, const TriangleMesh& mesh)
{
  double sum = 0.0;
  for (const Point3& p : mesh.points)
    sum += distanceToSurface(phantom, p);
  return sum / mesh.points.size();
}

/** A mask of this size (voxels) and spacing (mm), every voxel 0. */
MaskVolume::Pointer emptyMask(const std::array<std::size_t, 3>& size, const std::array<double, 3>& spacing)
{
  auto mask = MaskVolume::New();
  MaskVolume::SizeType itkSize;
  for (unsigned int axis = 0; axis < 3; ++axis)
    itkSize[axis] = size[axis];
  mask->SetRegions(itkSize);
  mask->SetSpacing(spacing.data());
  mask->Allocate(true);
  return mask;
}

/** Flying edges' triangle count on this grid for a surface of this area (SurfaceRemeshing.h). */
double flyingEdgesTriangles(double area, const std::array<double, 3>& s)
{
  return area * (1.0 / (s[0] * s[1]) + 1.0 / (s[0] * s[2]) + 1.0 / (s[1] * s[2]));
}

struct Finished
{
  PhantomMeshResult tiling;
  FinishedSurface surface;
  double tilingDistance = 0.0, finishedDistance = 0.0;
};

Finished finish(const Phantom& phantom, const PhantomTestGrid& grid)
{
  Finished f;
  f.tiling = meshPhantom(phantom, grid.spacing, grid.direction);
  const SurfaceFinishingOptions options = finishingOptionsFor(grid.spacing);
  // Physical space is the slice frame moved rigidly (mirrored or not): smoothing and remeshing do
  // not see the difference.
  f.surface = finishSurface(f.tiling.mesh, f.tiling.validation, options);
  f.tilingDistance = meanDistance(phantom, f.tiling.mesh);
  f.finishedDistance = meanDistance(phantom, f.surface.mesh);
  const MeshValidation& v = f.surface.validation;
  std::printf("%-13s %s%s; %zu -> %zu triangles (flying edges ~%.0f), under 30 deg %.2f%%, smallest %.1f deg, "
              "mean distance %.3f -> %.3f mm, volume %.1f -> %.1f mm^3\n",
              grid.name, finishName(f.surface.finish), f.surface.fallback.c_str(), f.tiling.mesh.triangles.size(),
              f.surface.mesh.triangles.size(), flyingEdgesTriangles(v.area, grid.spacing),
              100.0 * v.fractionAnglesBelow30, v.minAngleDegrees, f.tilingDistance, f.finishedDistance,
              f.tiling.validation.volume, v.volume);
  return f;
}

/** What every finished phantom must do. `closer`: the largest finished mean distance as a fraction
 *  of the tiling's (0: not compared); `ofHalfDiagonal`: the largest finished mean distance as a
 *  fraction of half the voxel diagonal (0: not compared). */
void expectFinished(const Phantom& phantom, const PhantomTestGrid& grid, double closer, double ofHalfDiagonal = 0.0)
{
  const Finished f = finish(phantom, grid);
  const MeshValidation& v = f.surface.validation;
  EXPECT_EQ(f.surface.finish, SurfaceFinish::Remeshed) << f.surface.fallback;
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, f.tiling.validation.components);
  EXPECT_EQ(v.eulerCharacteristic, f.tiling.validation.eulerCharacteristic);
  EXPECT_LT(v.fractionAnglesBelow30, 0.01);
  EXPECT_LT(static_cast<double>(f.surface.mesh.triangles.size()), flyingEdgesTriangles(v.area, grid.spacing));
  if (closer > 0.0)
    EXPECT_LT(f.finishedDistance, closer * f.tilingDistance);
  const auto& s = grid.spacing;
  const double halfDiagonal = 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  if (ofHalfDiagonal > 0.0)
    EXPECT_LT(f.finishedDistance, ofHalfDiagonal * halfDiagonal);
  // Taubin's filter keeps the volume; the remesh projects onto the smoothed surface.
  EXPECT_NEAR(v.volume, f.tiling.validation.volume, 0.02 * std::abs(f.tiling.validation.volume));
}

} // namespace

// Smooth shapes: the staircase is most of the tiling's error, and smoothing takes it out. Measured:
// the finished mean distance is 0.35-0.62 of the tiling's on the near-isotropic grids and 0.71-0.78
// at 0.8 x 0.8 x 3 mm, where the tiling's error is mostly the chords between thick slices.
TEST(SurfaceFinishingPhantom, Sphere)
{
  const Sphere sphere(Vector3(0.3, -0.2, 0.1), 15.0);
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFinished(sphere, grid, grid.spacing[2] > 2.5 ? 0.85 : 0.65);
}

TEST(SurfaceFinishingPhantom, TiltedTorus)
{
  const Torus torus(Vector3(0, 0, 0), Vector3(1, 0, 0.5), 14.0, 5.0);
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFinished(torus, grid, grid.spacing[2] > 2.5 ? 0.85 : 0.65);
}

TEST(SurfaceFinishingPhantom, RotatedBox)
{
  // Sharp edges: smoothing would round them over about a voxel (1.1-1.4 times the tiling's distance
  // without the displacement bound); with it the box ends 0.77-1.0 of the tiling's distance (1.0 on
  // the mirrored grid, whose 1.5 mm slices let its edges round over 0.45 mm across them; 0.97 there
  // when every piece got the grid's edge, before the edge followed how the faces meet the grid).
  const Box box(Vector3(0, 0, 0), Vector3(12, 8, 7), rotation({ 0, 1, 1 }, 0.5));
  for (const PhantomTestGrid& grid : phantomTestGrids())
    expectFinished(box, grid, 1.02, 0.2);
}

TEST(SurfaceFinishingPhantom, ThinBranchingTubeKeepsItsVolume)
{
  // Tubes of radius 1.5 mm (three voxels across at 1 mm): Taubin's filter shrinks shapes whose whole
  // cross section is above its pass band (without the volume restoration these tubes lost 16-42%),
  // and edges of about a voxel cut chords across a 3 mm tube. Measured: the finished volume is
  // 86-94% of the tiling's. Before the smoothing's displacement bound, the remeshed and smoothed tube
  // crossed itself at a branching on the oblique grid (90 pairs) and the stage fell back to the
  // smoothed tiling: what is asserted is that whatever is kept is valid, one piece of the same
  // genus, with the volume. (The tiling itself is 16-23% under the analytic volume here: contours
  // of a few pixels lose their corners to marching squares; not this stage's doing.)
  const TubeTree tubes({ { Vector3(0, 0, -12), Vector3(0, 0, 0) }, { Vector3(0, 0, 0), Vector3(8, 2, 10) },
                         { Vector3(0, 0, 0), Vector3(-7, -3, 11) } },
                       1.5);
  for (const PhantomTestGrid& grid : phantomTestGrids())
  {
    if (grid.spacing[2] > 2.5)
      continue; // 3 mm slices do not resolve a 3 mm tube
    const Finished f = finish(tubes, grid);
    EXPECT_TRUE(f.surface.validation.valid()) << f.surface.validation.summary();
    EXPECT_EQ(f.surface.validation.eulerCharacteristic, f.tiling.validation.eulerCharacteristic);
    EXPECT_EQ(f.surface.validation.components, 1u);
    EXPECT_NEAR(f.surface.validation.volume, f.tiling.validation.volume, 0.15 * f.tiling.validation.volume);
  }
}

TEST(SurfaceFinishingPhantom, ATubeAlongTheSlicesIsNotLeftInRingsOfNarrowTriangles)
{
  // Tubes of radius 3 mm on 1 x 1 x 1.5 mm voxels, the grid moved by (0.096, 0.355, 0.749) voxels
  // (the targets benchmark's branching tubes at its placement 5): there the remesh's rounds settled
  // on the trunk, along the slices, into rings of vertices half a slice apart split into right
  // triangles of 29 degrees (6.7% of the surface), which no split, collapse, valence flip or
  // relaxation changes, until the shortest edges of the narrow triangles were collapsed after them.
  const TubeTree tubes({ { Vector3(0, 0, -20), Vector3(0, 0, 0) }, { Vector3(0, 0, 0), Vector3(14, 4, 16) },
                         { Vector3(0, 0, 0), Vector3(-12, -5, 18) } },
                       3.0);
  const std::array<double, 3> spacing{ 1.0, 1.0, 1.5 };
  GridSpec grid = gridAround(tubes, spacing, 2);
  const double phi = 1.2207440846057596; // Roberts' R3 sequence, as SliceMeshBenchmark places phantoms
  double step = 1.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    step /= phi;
    grid.origin[axis] += std::fmod(5.0 * step, 1.0) * spacing[axis];
  }
  const MeshedMask meshed = meshMask(rasterizePhantom(tubes, grid), MeshingOptions{});
  const MeshValidation v = validateMesh(meshed.physical);
  const double distance = meanDistance(tubes, meshed.physical);
  std::printf("tubes at 1 x 1 x 1.5 mm, moved: %s, %zu triangles, under 30 deg %.2f%%, smallest %.1f deg, "
              "mean distance %.3f mm, volume %.1f of %.1f mm^3\n",
              finishName(meshed.meshing.surface.finish), meshed.physical.triangles.size(),
              100.0 * v.fractionAnglesBelow30, v.minAngleDegrees, distance, v.volume, tubes.volume());
  EXPECT_EQ(meshed.meshing.surface.finish, SurfaceFinish::Remeshed) << meshed.meshing.surface.fallback;
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_LT(v.fractionAnglesBelow30, 0.01);
  // The collapses keep the surface where the tubes are: a tenth of the slice spacing on average (the
  // targets benchmark measured 0.12 mm here), and the volume within 5% of the analytic one.
  EXPECT_LT(distance, 0.15);
  EXPECT_NEAR(v.volume, tubes.volume(), 0.05 * tubes.volume());
}

// Volumetry: the tiling's chords and marching squares' cut corners sit slightly inside a curved
// surface (its volume was 0.2-1.3% under the voxels'); the finished surface encloses the voxels'
// volume, on every grid, between the test grids too (0.9 x 0.9 x 2 mm), hollow shapes included.
TEST(SurfaceFinishingPhantom, TheFinishedSurfaceEnclosesTheVoxelsVolume)
{
  const Sphere sphere(Vector3(0.3, -0.2, 0.1), 15.0);
  const Torus torus(Vector3(0, 0, 0), Vector3(1, 0, 0.5), 14.0, 5.0);
  const Box box(Vector3(0, 0, 0), Vector3(12, 8, 7), rotation({ 0, 1, 1 }, 0.5));
  std::vector<PhantomTestGrid> grids = phantomTestGrids();
  grids.push_back({ "0.9x0.9x2", { 0.9, 0.9, 2.0 } });
  for (const Phantom* phantom : std::initializer_list<const Phantom*>{ &sphere, &torus, &box })
    for (const PhantomTestGrid& grid : grids)
    {
      const PhantomMeshResult r = meshPhantom(*phantom, grid.spacing, grid.direction, {}, {}, SurfaceFinish::Remeshed);
      const double error = r.validation.volume / r.voxelVolume - 1.0;
      std::printf("%-13s %s; volume %+.3f%% of the voxels'\n", grid.name, finishName(r.finish), 100.0 * error);
      EXPECT_TRUE(r.validation.valid()) << r.validation.summary();
      EXPECT_EQ(r.finish, SurfaceFinish::Remeshed) << r.fallback;
      EXPECT_LT(std::abs(error), 0.002) << grid.name;
    }
}

// On voxels longer along one axis than another the staircase is deeper across the long sides: the
// smoothing's bound is 0.3 of the voxel's side along each axis, not of the smallest side everywhere.
// Measured on this sphere (mean distance of the vertices): 0.042 mm against 0.052 with the smallest
// side's bound at 0.5 x 1 x 1 mm, 0.047 against 0.051 at 0.7 x 0.7 x 1.4 mm.
TEST(SurfaceFinishingPhantom, TheSmoothingBoundFollowsEachVoxelSide)
{
  const Sphere sphere(Vector3(0.3, -0.2, 0.1), 20.0);
  for (const PhantomTestGrid& grid : { PhantomTestGrid{ "0.5x1x1", { 0.5, 1.0, 1.0 } },
                                       PhantomTestGrid{ "0.7x0.7x1.4", { 0.7, 0.7, 1.4 } } })
  {
    const PhantomMeshResult tiling = meshPhantom(sphere, grid.spacing, grid.direction);
    SurfaceFinishingOptions perAxis = finishingOptionsFor(grid.spacing);
    SurfaceFinishingOptions smallestSide = perAxis;
    const double smallest = std::min({ grid.spacing[0], grid.spacing[1], grid.spacing[2] });
    smallestSide.smoothing.maxDisplacement.fill(0.3 * smallest);
    smallestSide.smoothing.maxDisplacementAwayFromFeatures.fill(0.5 * smallest);
    const FinishedSurface finished = finishSurface(tiling.mesh, tiling.validation, perAxis);
    const FinishedSurface bySmallestSide = finishSurface(tiling.mesh, tiling.validation, smallestSide);
    const double distance = meanDistance(sphere, finished.mesh);
    const double smallestSideDistance = meanDistance(sphere, bySmallestSide.mesh);
    std::printf("%-12s mean distance %.4f mm (bound of the smallest side: %.4f mm)\n", grid.name, distance,
                smallestSideDistance);
    EXPECT_EQ(finished.finish, SurfaceFinish::Remeshed) << finished.fallback;
    EXPECT_TRUE(finished.validation.valid()) << finished.validation.summary();
    EXPECT_LT(distance, 0.97 * smallestSideDistance) << grid.name;
    // Within a tenth of the smallest voxel side of the sphere, on average.
    EXPECT_LT(distance, 0.1 * std::min({ grid.spacing[0], grid.spacing[1], grid.spacing[2] })) << grid.name;
  }
}

// On a grid whose slices are thinner than its pixels (or whose pixels are far from square) the bound
// is a flat ellipsoid. A vertex on a wall across the slices drifts along it while the pixels'
// staircase is smoothed out across it; a move that leaves the ellipsoid goes to its nearest point,
// which keeps the move across the wall, not to the move scaled down as a whole, which shortened it
// by the drift. Measured (mean distance of the vertices): 0.0318 mm against 0.0343 scaled at
// 1 x 1 x 0.5 mm, 0.0766 against 0.0923 at 2 x 0.5 x 1 mm.
TEST(SurfaceFinishingPhantom, AWallAcrossThinSlicesIsSmoothedAcrossItsPixels)
{
  struct Case
  {
    PhantomTestGrid grid;
    double largestSideFraction; ///< the mean distance stays under this fraction of the largest side
  };
  const Sphere sphere(Vector3(0.3, -0.2, 0.1), 20.0);
  for (const auto& [grid, largestSideFraction] : { Case{ { "1x1x0.5", { 1.0, 1.0, 0.5 } }, 0.033 },
                                                   Case{ { "2x0.5x1", { 2.0, 0.5, 1.0 } }, 0.042 } })
  {
    const PhantomMeshResult finished = meshPhantom(sphere, grid.spacing, grid.direction, {}, {}, SurfaceFinish::Remeshed);
    const double distance = meanDistance(sphere, finished.mesh);
    const double largest = std::max({ grid.spacing[0], grid.spacing[1], grid.spacing[2] });
    std::printf("%-8s mean distance %.4f mm (%.4f of the largest voxel side)\n", grid.name, distance, distance / largest);
    EXPECT_EQ(finished.finish, SurfaceFinish::Remeshed) << finished.fallback;
    EXPECT_TRUE(finished.validation.valid()) << finished.validation.summary();
    EXPECT_LT(finished.validation.fractionAnglesBelow30, 0.01);
    EXPECT_LT(distance, largestSideFraction * largest) << grid.name;
  }
}

// After the first 50 pairs the smoothing holds sharp features and goes on elsewhere, 80 pairs more
// within half a voxel: a gently curved surface's terraces are longer than 100 pairs reach, while more
// pairs on a box's edges would only round them. Against the whole surface filtered 100 pairs within 0.3 of a
// voxel (the smoothing before), on grids between the benchmark's two, where spheres were farther
// from the true surface than 3D Slicer's.
TEST(SurfaceFinishingPhantom, SharpFeaturesAreHeldWhileGentleCurvesAreSmoothedFurther)
{
  const Sphere sphere(Vector3(0.3, -0.2, 0.1), 20.0);
  const Box box(Vector3(0, 0, 0), Vector3(12, 8, 7), rotation({ 0, 1, 1 }, 0.5));
  for (const PhantomTestGrid& grid : { PhantomTestGrid{ "0.8x0.8x0.9", { 0.8, 0.8, 0.9 } },
                                       PhantomTestGrid{ "0.5x1x1", { 0.5, 1.0, 1.0 } } })
  {
    const SurfaceFinishingOptions held = finishingOptionsFor(grid.spacing);
    SurfaceFinishingOptions whole = held;
    whole.smoothing.iterations = 100;
    whole.smoothing.featurePairs = 100;
    for (const Phantom* phantom : { static_cast<const Phantom*>(&sphere), static_cast<const Phantom*>(&box) })
    {
      const PhantomMeshResult tiling = meshPhantom(*phantom, grid.spacing, grid.direction);
      const FinishedSurface a = finishSurface(tiling.mesh, tiling.validation, held);
      const FinishedSurface b = finishSurface(tiling.mesh, tiling.validation, whole);
      const double heldDistance = meanDistance(*phantom, a.mesh), wholeDistance = meanDistance(*phantom, b.mesh);
      const bool isSphere = phantom == &sphere;
      std::printf("%-12s %-6s mean distance %.4f mm (whole surface, 100 pairs: %.4f mm), under 30 deg %.2f%%, "
                  "volume %.1f of %.1f mm^3\n",
                  grid.name, isSphere ? "sphere" : "box", heldDistance, wholeDistance,
                  100.0 * a.validation.fractionAnglesBelow30, a.validation.volume, phantom->volume());
      EXPECT_EQ(a.finish, SurfaceFinish::Remeshed) << a.fallback;
      EXPECT_TRUE(a.validation.valid()) << a.validation.summary();
      EXPECT_LT(a.validation.fractionAnglesBelow30, 0.01);
      // Measured: the sphere 0.944 and 0.915 of the whole surface's distance, the box 0.935 and 0.939.
      EXPECT_LT(heldDistance, (isSphere ? 0.97 : 1.0) * wholeDistance) << grid.name;
      // The volume is the tiling's here (finishSurface alone), which sits slightly inside the shape:
      // within 1.5% of the analytic volume (measured 0.3-0.9% under).
      EXPECT_NEAR(a.validation.volume, phantom->volume(), 0.015 * phantom->volume()) << grid.name;
    }
  }
}

// Each connected piece encloses its own voxels' volume. Before, the label's voxels were shared among
// the pieces in proportion to their tiled volumes: a single voxel is tiled at a sixth of its volume
// (and left so), so the large pieces made up for the specks: a 10 mm cube beside twenty single
// voxels came out 1.7% too large, and with a thousand it was not given its volume at all.
TEST(SurfaceFinishingPhantom, EachPieceEnclosesItsOwnVoxels)
{
  for (const std::array<double, 3>& spacing : { std::array<double, 3>{ 1.0, 1.0, 1.0 }, std::array<double, 3>{ 0.6, 0.8, 2.0 } })
  {
    const MaskVolume::Pointer mask = emptyMask({ 40, 34, 16 }, spacing);
    auto set = [&](long i, long j, long k) { mask->SetPixel({ { i, j, k } }, 1); };
    for (long k = 2; k < 12; ++k)
      for (long j = 2; j < 12; ++j)
        for (long i = 2; i < 12; ++i)
          set(i, j, k); // 1000 voxels
    for (long k = 4; k < 8; ++k)
      for (long j = 20; j < 27; ++j)
        for (long i = 20; i < 26; ++i)
          set(i, j, k); // 168 voxels
    for (long s = 0; s < 20; ++s)
      set(16 + (s % 5) * 4, 3 + (s / 5) * 3, 3 + (s % 3) * 4); // single voxels three apart
    const double voxel = spacing[0] * spacing[1] * spacing[2];
    const MeshedMask meshed = meshMask(mask, MeshingOptions{});
    double shares = 0.0;
    for (const ContourVolume& share : meshed.meshing.targetShares)
      shares += share.volume;
    EXPECT_NEAR(shares, 1188 * voxel, 1e-9 * voxel); // the traced contours' pixels are the voxels

    std::vector<double> volumes;
    for (const TriangleMesh& piece : splitIntoPieces(meshed.meshing.surface.mesh))
      volumes.push_back(validateMesh(piece).volume);
    ASSERT_EQ(volumes.size(), 22u);
    std::sort(volumes.begin(), volumes.end());
    std::printf("%.1f x %.1f x %.1f mm: pieces %.2f and %.2f voxels, single voxels %.3f to %.3f\n", spacing[0], spacing[1],
                spacing[2], volumes[21] / voxel, volumes[20] / voxel, volumes[0] / voxel, volumes[19] / voxel);
    EXPECT_TRUE(meshed.meshing.surface.validation.valid()) << meshed.meshing.surface.validation.summary();
    EXPECT_NEAR(volumes[21], 1000 * voxel, 0.002 * 1000 * voxel);
    EXPECT_NEAR(volumes[20], 168 * voxel, 0.01 * 168 * voxel);
    EXPECT_GT(volumes[0], 0.0);
    // A single voxel is tiled at a sixth of its volume and given back at most half again that.
    EXPECT_LT(volumes[19], voxel);
  }
}

// A piece's volume does not depend on what else the label holds. A plate one slice thick is tiled at
// about half of its voxels' volume; alone it was given its voxels' volume, but beside another piece it
// followed its target only within a quarter of its tiled volume, and was left at half. Given its
// volume, it stays where its voxels are.
TEST(SurfaceFinishingPhantom, AThinPieceEnclosesItsVoxelsAloneAndBesideAnother)
{
  for (const std::array<double, 3>& spacing : { std::array<double, 3>{ 1.0, 1.0, 1.0 }, std::array<double, 3>{ 0.7, 0.9, 2.5 } })
  {
    // The plate: voxels i 3..32, j 3..5, k 5 (origin 0, no rotation: voxel (i, j, k) is centred at
    // (i, j, k) times the spacing), 90 voxels in one slice.
    const std::array<long, 3> low{ 3, 3, 5 }, high{ 32, 5, 5 };
    auto plate = [&](bool withBlock)
    {
      const MaskVolume::Pointer mask = emptyMask({ 40, 34, 12 }, spacing);
      for (long j = low[1]; j <= high[1]; ++j)
        for (long i = low[0]; i <= high[0]; ++i)
          mask->SetPixel({ { i, j, low[2] } }, 1);
      if (withBlock)
        for (long k = 3; k < 9; ++k)
          for (long j = 20; j < 28; ++j)
            for (long i = 10; i < 20; ++i)
              mask->SetPixel({ { i, j, k } }, 1);
      const MeshedMask meshed = meshMask(mask, MeshingOptions{});
      EXPECT_TRUE(meshed.meshing.surface.validation.valid()) << meshed.meshing.surface.validation.summary();
      std::vector<TriangleMesh> pieces = splitIntoPieces(meshed.physical);
      EXPECT_EQ(pieces.size(), withBlock ? 2u : 1u);
      // The plate is the smaller piece.
      std::sort(pieces.begin(), pieces.end(), [](const TriangleMesh& a, const TriangleMesh& b)
                { return validateMesh(a).volume < validateMesh(b).volume; });
      return pieces.front();
    };
    // How far outside the plate's voxels (their outer faces) a vertex lies, in voxel sides along
    // each axis: the largest over the vertices and axes.
    auto beyondVoxels = [&](const TriangleMesh& mesh)
    {
      double farthest = 0.0;
      for (const Point3& p : mesh.points)
      {
        const double c[3] = { p.x, p.y, p.z };
        for (int a = 0; a < 3; ++a)
        {
          const double below = (low[a] - 0.5) * spacing[a] - c[a], above = c[a] - (high[a] + 0.5) * spacing[a];
          farthest = std::max(farthest, std::max(below, above) / spacing[a]);
        }
      }
      return farthest;
    };
    const double voxels = 90 * spacing[0] * spacing[1] * spacing[2];
    const TriangleMesh alone = plate(false), beside = plate(true);
    const double aloneVolume = validateMesh(alone).volume, besideVolume = validateMesh(beside).volume;
    std::printf("%.1f x %.1f x %.1f mm: the plate alone %.4f, beside a block %.4f of its voxels; farthest vertex "
                "%.3f and %.3f voxel sides outside them\n",
                spacing[0], spacing[1], spacing[2], aloneVolume / voxels, besideVolume / voxels, beyondVoxels(alone),
                beyondVoxels(beside));
    EXPECT_NEAR(aloneVolume, voxels, 0.02 * voxels);
    EXPECT_NEAR(besideVolume, aloneVolume, 0.01 * voxels);
    // Within three quarters of a voxel side of the voxels' faces. A plate one slice thick is tiled
    // with domed edges, thinner than its voxels there, so to hold their volume its middle stands out
    // past their faces a little (measured: 0.46 of a side at 1 mm, across the slice; 0.62 at
    // 0.7 x 0.9 x 2.5 mm, across the plate's 3 pixels).
    EXPECT_LE(beyondVoxels(alone), 0.75);
    EXPECT_LE(beyondVoxels(beside), 0.75);
  }
}

// A tube about as thin as the remesh's edge, winding obliquely through the slices (a white-matter
// tract a voxel or two across): the remesh and the smoothing leave needles and caps on it that the
// relaxation does not undo, and the finishing then flips and collapses them away where they are.
// Measured: radius 1 voxel, 0.0% of the triangles under 30 degrees (0.3% before the widening);
// radius 0.8, 2.0% (6.8% before).
TEST(SurfaceFinishingPhantom, AThinWindingTubeIsLeftWithoutItsNeedles)
{
  for (const double radius : { 1.0, 0.8 })
  {
    const MaskVolume::Pointer mask = emptyMask({ 40, 40, 40 }, { 1.0, 1.0, 1.0 });
    // The tube's axis, densely sampled: a tilted line with a wave in y and z.
    std::vector<Point3> axis;
    for (int i = 0; i < 200; ++i)
    {
      const double t = i / 199.0;
      axis.push_back({ 5.0 + 30.0 * t, 20.0 + 8.0 * std::sin(6.0 * t), 5.0 + 28.0 * t + 3.0 * std::cos(5.0 * t) });
    }
    std::size_t voxels = 0;
    for (long k = 0; k < 40; ++k)
      for (long j = 0; j < 40; ++j)
        for (long i = 0; i < 40; ++i)
          for (const Point3& c : axis)
            if ((i - c.x) * (i - c.x) + (j - c.y) * (j - c.y) + (k - c.z) * (k - c.z) <= radius * radius)
            {
              mask->SetPixel({ { i, j, k } }, 1);
              ++voxels;
              break;
            }
    const MeshedMask meshed = meshMask(mask, MeshingOptions{});
    const FinishedSurface& finished = meshed.meshing.surface;
    const MeshValidation& v = finished.validation;
    std::printf("radius %.1f: %zu voxels, %zu triangles, %zu widening operations, %.2f%% under 30 degrees, "
                "smallest %.1f, volume %.1f mm^3\n",
                radius, voxels, finished.mesh.triangles.size(), finished.narrowTrianglesWidened,
                100.0 * v.fractionAnglesBelow30, measureMeshQuality(finished.mesh).minAngleDegrees, v.volume);
    EXPECT_EQ(finished.finish, SurfaceFinish::Remeshed) << finished.fallback;
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_GT(finished.narrowTrianglesWidened, 0u);
    EXPECT_LT(v.fractionAnglesBelow30, radius == 1.0 ? 0.001 : 0.03);
    // Where the voxels are: the tube keeps its voxels' volume (the finishing's volume target, before
    // the widening's collapses, which move no point).
    EXPECT_NEAR(v.volume, static_cast<double>(voxels), 0.05 * static_cast<double>(voxels));
    // And where the tube is: the voxels in it are those whose centres lie within the radius of the
    // axis. Its surface is measured by its distance from the densely sampled axis (the mask's origin
    // is the first voxel's centre, 1 mm voxels), at each triangle's corners, edge midpoints and
    // centroid, weighted by area, against the radius of the tube (capped at both ends) that holds the
    // voxels' volume.
    auto fromAxis = [&](const Point3& p)
    {
      double d2 = 1e18;
      for (std::size_t i = 0; i + 1 < axis.size(); ++i)
      {
        const Point3 a = axis[i], b = axis[i + 1];
        const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
        const double t = std::clamp(((p.x - a.x) * ux + (p.y - a.y) * uy + (p.z - a.z) * uz) /
                                      (ux * ux + uy * uy + uz * uz), 0.0, 1.0);
        const double dx = p.x - a.x - t * ux, dy = p.y - a.y - t * uy, dz = p.z - a.z - t * uz;
        d2 = std::min(d2, dx * dx + dy * dy + dz * dz);
      }
      return std::sqrt(d2);
    };
    const TriangleMesh& surface = meshed.physical;
    double weighted = 0.0, area = 0.0, farthest = 0.0, nearest = 1e9;
    for (const Triangle& t : surface.triangles)
    {
      const Point3 a = surface.points[static_cast<std::size_t>(t[0])], b = surface.points[static_cast<std::size_t>(t[1])],
                   c = surface.points[static_cast<std::size_t>(t[2])];
      auto mix = [](const Point3& p, const Point3& q, const Point3& r, double u, double v, double w)
      { return Point3{ u * p.x + v * q.x + w * r.x, u * p.y + v * q.y + w * r.y, u * p.z + v * q.z + w * r.z }; };
      const Point3 n = areaNormal(surface, t);
      const double triangleArea = 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      const Point3 samples[7] = { a, b, c, mix(a, b, c, 0.5, 0.5, 0.0), mix(a, b, c, 0.0, 0.5, 0.5),
                                  mix(a, b, c, 0.5, 0.0, 0.5), mix(a, b, c, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0) };
      // Simpson-like weights on a triangle: corners 1/20, edge midpoints 2/15, centroid 9/20.
      const double weights[7] = { 0.05, 0.05, 0.05, 2.0 / 15.0, 2.0 / 15.0, 2.0 / 15.0, 0.45 };
      for (int k = 0; k < 7; ++k)
      {
        const double d = fromAxis(samples[k]);
        weighted += weights[k] * triangleArea * d;
        farthest = std::max(farthest, d);
        nearest = std::min(nearest, d);
      }
      area += triangleArea;
    }
    const double mean = weighted / area;
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < axis.size(); ++i)
      length += std::sqrt((axis[i + 1].x - axis[i].x) * (axis[i + 1].x - axis[i].x) +
                          (axis[i + 1].y - axis[i].y) * (axis[i + 1].y - axis[i].y) +
                          (axis[i + 1].z - axis[i].z) * (axis[i + 1].z - axis[i].z));
    double low = 0.0, high = 3.0; // bisection for the voxels' tube radius
    for (int step = 0; step < 60; ++step)
    {
      const double r = 0.5 * (low + high);
      (M_PI * r * r * length + 4.0 / 3.0 * M_PI * r * r * r < static_cast<double>(voxels) ? low : high) = r;
    }
    std::printf("radius %.1f: the surface %.3f to %.3f mm from the axis, %.3f on average; the voxels' tube %.3f\n",
                radius, nearest, farthest, mean, low);
    // Measured: 1.026 against 1.011 mm, and 0.809 against 0.787. (The nearest point says little: where
    // the tube is one voxel across, its surface passes half a voxel from that voxel's centre, which
    // can lie off the axis by almost as much.)
    EXPECT_NEAR(mean, low, 0.1);
    EXPECT_LE(farthest, radius + 0.5 * std::sqrt(3.0)); // the voxels' outermost corners
  }
}

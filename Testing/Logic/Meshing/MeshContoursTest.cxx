// The one meshing path: automatic options resolved from the grid in one place, the stages run one by
// one giving what meshContours gives, and what each stage leaves behind.
#include "ContourStacks.h"
#include "Contours/ContourStacking.h"
#include "Meshing/MeshContours.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slicemesh::testing
{
namespace
{

/** A ball of radius 6 mm sliced every 1.5 mm: circles of 64 points. */
ContourStack ballStack()
{
  ContourStack stack;
  stack.sliceSpacing = 1.5;
  for (double z = -5.25; z <= 5.3; z += 1.5)
    stack.slices.push_back({ z, { circle(0.0, 0.0, std::sqrt(36.0 - z * z), 64) } });
  return stack;
}

TEST(MeshingOptions, AutomaticValuesComeFromTheGrid)
{
  // 0.8 x 0.8 x 3 mm: the finishing's edge is 1.1 times the flying-edges-equivalent edge
  // sqrt(3 / (1/0.64 + 2/2.4)) mm, its displacement bound 0.3 of the voxel's side along each axis.
  const MeshingOptions resolved = resolvedMeshingOptions({}, { 0.8, 0.8, 3.0 });
  EXPECT_NEAR(resolved.finishing.remeshing.targetEdgeLength, 1.1 * std::sqrt(3.0 / (1.0 / 0.64 + 2.0 / 2.4)), 1e-12);
  EXPECT_NEAR(resolved.finishing.smoothing.maxDisplacement[0], 0.24, 1e-12);
  EXPECT_NEAR(resolved.finishing.smoothing.maxDisplacement[1], 0.24, 1e-12);
  EXPECT_NEAR(resolved.finishing.smoothing.maxDisplacement[2], 0.9, 1e-12);
  EXPECT_EQ(resolved.contours.mode, ContourPreparation::Traced); // the default is not automatic
  // Remeshed (the default): the traced contours are resampled to a little over the target edge.
  EXPECT_NEAR(resolved.contours.pointSpacing, remeshedContourSpacing * resolved.finishing.remeshing.targetEdgeLength, 1e-12);
  // Near-isotropic voxels: the traced contours, which coincide along the voxel walls, are kept.
  EXPECT_EQ(resolvedMeshingOptions({}, { 1.0, 1.0, 1.1 }).contours.pointSpacing, 0.0);
  MeshingOptions smoothedOnly;
  smoothedOnly.finishing.finish = SurfaceFinish::Smoothed;
  EXPECT_EQ(resolvedMeshingOptions(smoothedOnly, { 0.8, 0.8, 3.0 }).contours.pointSpacing, 0.0); // traced points kept
  // Remeshed, traced contours kept at their points lose those on straight runs (a thousandth of the
  // smaller pixel); contours resampled anyway are not simplified first;
  // a surface left smoothed or tiled keeps every traced point, and a given tolerance is kept.
  EXPECT_NEAR(resolvedMeshingOptions({}, { 0.8, 0.7, 0.8 }).contours.simplificationTolerance, 0.7e-3, 1e-15);
  EXPECT_EQ(resolvedMeshingOptions(smoothedOnly, { 0.8, 0.8, 0.8 }).contours.simplificationTolerance, 0.0);
  EXPECT_EQ(resolvedMeshingOptions({}, { 0.8, 0.8, 3.0 }).contours.simplificationTolerance, 0.0); // resampled
  MeshingOptions simplified;
  simplified.contours.simplificationTolerance = 0.2;
  EXPECT_EQ(resolvedMeshingOptions(simplified, { 0.8, 0.8, 3.0 }).contours.simplificationTolerance, 0.2);
  MeshingOptions spaced;
  spaced.contours.pointSpacing = 0.5;
  EXPECT_EQ(resolvedMeshingOptions(spaced, { 0.8, 0.8, 3.0 }).contours.pointSpacing, 0.5);

  MeshingOptions automatic;
  automatic.contours.mode = ContourPreparation::Automatic;
  const MeshingOptions thick = resolvedMeshingOptions(automatic, { 0.8, 0.8, 3.0 });
  EXPECT_EQ(thick.contours.mode, ContourPreparation::Smoothed);
  EXPECT_NEAR(thick.contours.pointSpacing, std::sqrt(0.8 * 3.0), 1e-12);
  EXPECT_NEAR(thick.contours.smoothingMaxShift, 0.24, 1e-12);
  EXPECT_EQ(resolvedMeshingOptions(automatic, { 1.0, 1.0, 1.0 }).contours.mode, ContourPreparation::Traced);

  // Given values are kept.
  MeshingOptions given;
  given.finishing.remeshing.targetEdgeLength = 2.5;
  given.finishing.smoothing.maxDisplacement = { 0.1, 0.1, 0.2 };
  const MeshingOptions kept = resolvedMeshingOptions(given, { 1.0, 1.0, 1.0 });
  EXPECT_EQ(kept.finishing.remeshing.targetEdgeLength, 2.5);
  EXPECT_EQ(kept.finishing.smoothing.maxDisplacement, (std::array<double, 3>{ 0.1, 0.1, 0.2 }));
}

TEST(MeshContours, StageByStageIsMeshContours)
{
  const ContourStack stack = ballStack();
  const std::array<double, 3> spacing{ 0.5, 0.5, 1.5 };
  std::vector<MeshingStage> heard;
  const MeshedContours whole = meshContours(stack, {}, spacing,
                                            [&](MeshingStage stage, double fraction)
                                            {
                                              EXPECT_GE(fraction, 0.0);
                                              EXPECT_LE(fraction, 1.0);
                                              if (heard.empty() || heard.back() != stage)
                                                heard.push_back(stage);
                                            });
  EXPECT_EQ(heard, std::vector<MeshingStage>{ MeshingStage::Tiling }); // the stage that reports its fraction

  MeshedContours byStage = startMeshing(stack, {}, spacing);
  runMeshingStage(MeshingStage::Preparation, byStage);
  runMeshingStage(MeshingStage::Correspondence, byStage);
  runMeshingStage(MeshingStage::Tiling, byStage);
  EXPECT_FALSE(byStage.tiling.triangles.empty());
  EXPECT_TRUE(byStage.surface.mesh.triangles.empty()); // not finished yet
  runMeshingStage(MeshingStage::Validation, byStage);
  // Finished by default: the tiling's self-intersection test is left to the finishing.
  EXPECT_TRUE(byStage.tilingValidation.soundTopology()) << byStage.tilingValidation.summary();
  EXPECT_FALSE(byStage.tilingValidation.selfIntersectionChecked);
  EXPECT_TRUE(validateMesh(byStage.tiling).valid());
  runMeshingStage(MeshingStage::Finishing, byStage);
  EXPECT_EQ(byStage.surface.mesh.points.size(), whole.surface.mesh.points.size());
  EXPECT_EQ(byStage.surface.mesh.triangles, whole.surface.mesh.triangles);
  for (std::size_t v = 0; v < whole.surface.mesh.points.size(); ++v)
    ASSERT_EQ(byStage.surface.mesh.points[v].x, whole.surface.mesh.points[v].x);
}

TEST(MeshContours, TheFinishedBallIsValidCloseToTheSphereAndMeasured)
{
  const MeshedContours m = meshContours(ballStack(), {}, { 0.5, 0.5, 1.5 });
  EXPECT_EQ(m.surface.finish, SurfaceFinish::Remeshed) << m.surface.fallback;
  EXPECT_TRUE(m.surface.validation.valid()) << m.surface.validation.summary();
  EXPECT_EQ(m.measures.genus, 0);
  EXPECT_EQ(m.measures.sliceSpacing, 1.5);
  EXPECT_GT(m.measures.dirichlet.energy, 0.0); // the tiling's
  EXPECT_EQ(m.measures.shape.triangles, m.surface.mesh.triangles.size());
  // The caps reach half a slice beyond the end contours (z = +-6 mm): every vertex within 0.35 mm of
  // the sphere (a dome's rim, a quarter circle of half a slice over a 2.9 mm contour, stands farthest
  // out), on average within 0.1 mm; the volume within 3% of the ball's.
  double sum = 0.0;
  for (const Point3& p : m.surface.mesh.points)
  {
    const double distance = std::abs(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) - 6.0);
    EXPECT_LE(distance, 0.35);
    sum += distance;
  }
  EXPECT_LT(sum / static_cast<double>(m.surface.mesh.points.size()), 0.1);
  EXPECT_NEAR(m.surface.validation.volume, 4.0 / 3.0 * M_PI * 216.0, 0.03 * 4.0 / 3.0 * M_PI * 216.0);
}

TEST(MeshContours, ALongStraightRunIsTiledInEdgesOfAFewTargetEdges)
{
  // A bar one voxel thick and 400 long in one slice of 1 mm voxels, its long sides a point every
  // voxel. Tiled from the run's ends alone, its walls and caps were needles 400 mm long, which the
  // remesh halved into needles again: time and memory grew with the square of the length.
  const double length = 400.0;
  Polygon2 bar;
  for (double x = 0.0; x <= length; x += 1.0)
    bar.push_back({ x, 0.0 });
  for (double x = length; x >= 0.0; x -= 1.0)
    bar.push_back({ x, 1.0 });
  ContourStack stack;
  stack.sliceSpacing = 1.0;
  stack.slices.push_back({ 0.0, { bar } });
  MeshedContours m = startMeshing(stack, {}, { 1.0, 1.0, 1.0 });
  for (MeshingStage stage : { MeshingStage::Preparation, MeshingStage::Correspondence, MeshingStage::Tiling })
    runMeshingStage(stage, m, {});
  const double target = m.options.finishing.remeshing.targetEdgeLength;
  double longest = 0.0;
  for (const Triangle& t : m.tiling.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const Point3& a = m.tiling.points[t[k]];
      const Point3& b = m.tiling.points[t[(k + 1) % 3]];
      longest = std::max(longest, std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)));
    }
  // A cap's diagonal across the bar: the bound plus the bar's width at most.
  EXPECT_LE(longest, simplifiedEdgeBound * target + 1.0);
  for (MeshingStage stage : { MeshingStage::Validation, MeshingStage::Finishing })
    runMeshingStage(stage, m, {});
  EXPECT_EQ(m.surface.finish, SurfaceFinish::Remeshed) << m.surface.fallback;
  EXPECT_TRUE(m.surface.validation.valid()) << m.surface.validation.summary();
  EXPECT_EQ(m.measures.genus, 0);
  // The bar's voxels, 400 mm^3, within 2% (its square section is rounded, within the smoothing's
  // bound); about as many triangles as its area holds of the target.
  EXPECT_NEAR(m.surface.validation.volume, length, 0.02 * length);
  const double area = 2.0 * length * 2.0 + 2.0;
  EXPECT_LT(static_cast<double>(m.surface.mesh.triangles.size()), 3.0 * area / (0.25 * std::sqrt(3.0) * target * target));
}

/** Nine circles of radius 20 mm (64 points) about (c, c, c), 2.5 mm apart along a normal tilted by
 *  `degrees` about x, coordinates rounded to `decimals` as a planning system writes them, or to
 *  single precision (decimals < 0) as 3D Slicer keeps planar contours. */
std::vector<Polygon3> tiltedRoundedCylinder(double degrees, int decimals, double c = 0.0)
{
  const double t = degrees * M_PI / 180.0, scale = std::pow(10.0, decimals);
  auto rounded = [scale, decimals, c](double v) -> double
  {
    if (decimals >= 0)
      return std::round((c + v) * scale) / scale;
    const volatile float single = static_cast<float>(c + v); // GCC 12's vectorizer dropped a plain cast
    return single;
  };
  std::vector<Polygon3> contours;
  for (int k = 0; k < 9; ++k)
  {
    Polygon3 contour;
    for (const Point2& p : circle(0.0, 0.0, 20.0, 64))
    {
      const double z = 2.5 * k;
      contour.push_back({ rounded(p.x), rounded(p.y * std::cos(t) - z * std::sin(t)),
                          rounded(p.y * std::sin(t) + z * std::cos(t)) });
    }
    contours.push_back(std::move(contour));
  }
  return contours;
}

TEST(MeshContours, ContoursOnTiltedPlanesRoundedToAFewDecimalsAreMeshed)
{
  // Drawn at one place on adjacent tilted planes, two slices' points differ by their rounding. With
  // a fixed micrometre tolerance some pairs were one point and others not: at five and six decimals
  // most such stacks were refused ("contours of the slice touch each other"), and one ran until
  // the machine's memory was gone.
  // So with single precision (3D Slicer's planar contours) a hundred millimetres from the origin.
  const double area = 0.5 * 64.0 * 400.0 * std::sin(2.0 * M_PI / 64.0);
  for (const int decimals : { 3, 5, 6, 7, -1 })
    for (const double degrees : { 2.0, 6.0, 15.0 })
    {
      const StackedContours stacked = stackContours(tiltedRoundedCylinder(degrees, decimals, decimals < 0 ? 100.0 : 0.0));
      ASSERT_EQ(stacked.stack.slices.size(), 9u);
      EXPECT_GT(stacked.stack.coordinateStep, 0.0);
      MeshingOptions options;
      options.contours.pointSpacing = stacked.spacing[0]; // as the executable resamples a structure set
      const MeshedContours m = meshContours(stacked.stack, options, stacked.spacing);
      SCOPED_TRACE(std::to_string(decimals) + " decimals (-1: single precision), " + std::to_string(degrees) + " degrees");
      EXPECT_TRUE(m.surface.validation.valid()) << m.surface.validation.summary();
      EXPECT_EQ(m.measures.genus, 0);
      // Half a slice beyond the end contours: nine slices' worth of the 64-gon.
      EXPECT_NEAR(m.surface.validation.volume, 9.0 * 2.5 * area, 1e-3 * 9.0 * 2.5 * area);
      // Against the analytic prism, in the stack's frame: its axis through the contours' centre,
      // its ends half a slice beyond the first and last contours. The wall between the second and
      // the eighth slice (away from the caps' rounded rims) lies within 0.45 mm of the drawn circle,
      // 0.25 mm on average (measured: at most 0.36 and 0.20 mm, outwards: the offset that gives the
      // piece the prism's volume makes up for the rims); the caps reach the prism's ends and no more
      // than 0.5 mm beyond them (measured 0.42 mm: domed by the smoothing).
      const std::vector<Slice>& slices = stacked.stack.slices;
      Point2 centre{ 0.0, 0.0 };
      for (const Point2& p : slices.front().contours.front())
        centre = { centre.x + p.x / 64.0, centre.y + p.y / 64.0 };
      double worstWall = 0.0, sumWall = 0.0, lowest = 1e9, highest = -1e9;
      std::size_t wall = 0;
      for (const Point3& p : m.surface.mesh.points)
      {
        lowest = std::min(lowest, p.z);
        highest = std::max(highest, p.z);
        if (p.z <= slices[1].z || p.z >= slices[7].z)
          continue;
        const double off = std::abs(std::hypot(p.x - centre.x, p.y - centre.y) - 20.0);
        worstWall = std::max(worstWall, off);
        sumWall += off;
        ++wall;
      }
      ASSERT_GT(wall, 0u);
      EXPECT_LT(worstWall, 0.45);
      EXPECT_LT(sumWall / static_cast<double>(wall), 0.25);
      EXPECT_LE(lowest, slices.front().z - 1.25);
      EXPECT_GE(lowest, slices.front().z - 1.25 - 0.5);
      EXPECT_GE(highest, slices.back().z + 1.25);
      EXPECT_LE(highest, slices.back().z + 1.25 + 0.5);
    }
}

TEST(MeshContours, AFloodOfCrossingPointsFailsInsteadOfTakingEveryByte)
{
  // The same stack with its rounding not known (a micrometre tolerance against five decimals): the
  // slices' edges cross every few micrometres. The tiling may refuse it, but within the memory of
  // an ordinary run: its rows are no closer than half the contours' own edges, and the candidate
  // edges' grid no finer than the edges it holds (it had asked for 24 GB).
  StackedContours stacked = stackContours(tiltedRoundedCylinder(2.0, 5));
  stacked.stack.coordinateStep = 0.0;
  MeshingOptions options;
  options.contours.pointSpacing = stacked.spacing[0];
  try
  {
    const MeshedContours m = meshContours(stacked.stack, options, stacked.spacing);
    EXPECT_TRUE(m.surface.validation.valid()) << m.surface.validation.summary();
  }
  catch (const Error&)
  {
    SUCCEED() << "refused: the stack's slices do not meet only at common points";
  }
}

TEST(MeshContours, NoContoursIsAnErrorNotAnEmptyMesh)
{
  ContourStack empty;
  empty.slices = { { 0.0, {} }, { 1.0, {} } };
  EXPECT_THROW(meshContours(empty, {}, { 1.0, 1.0, 1.0 }), Error);
}

} // namespace
} // namespace slicemesh::testing

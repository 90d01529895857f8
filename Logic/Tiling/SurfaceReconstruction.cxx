#include "Tiling/SurfaceReconstruction.h"

#include "Contours/ContourCrossings.h"
#include "Contours/ContourNesting.h"
#include "Correspondence/MutualIntersections.h"
#include "Core/ParallelFor.h"
#include "Core/PlanarGeometry.h"
#include "Tiling/SlabTiling.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slicemesh
{

namespace
{

void checkStack(const ContourStack& stack)
{
  for (std::size_t k = 0; k < stack.slices.size(); ++k)
  {
    if (!std::isfinite(stack.slices[k].z))
      throw Error("contour stack: slice " + std::to_string(k) + " has a non-finite height");
    if (k > 0 && !(stack.slices[k].z > stack.slices[k - 1].z))
      throw Error("contour stack: slice heights must increase strictly (slice " + std::to_string(k) + ")");
  }
  if (!(stack.sliceSpacing >= 0.0) || !std::isfinite(stack.sliceSpacing))
    throw Error("contour stack: slice spacing must be zero (automatic) or positive, and finite");
  if (stack.slices.size() == 1 && stack.sliceSpacing == 0.0)
    throw Error("contour stack: a single slice needs its slice spacing (thickness) set");
}

bool onOneLine(const Polygon2& contour)
{
  for (std::size_t i = 2; i < contour.size(); ++i)
    if (orientation(contour[0], contour[1], contour[i]) != 0)
      return false;
  return true;
}

/** Contours of a slice must be simple and apart (a mask's contours always are); crossing or touching
 *  ones, which hand-made contours can have, have no inside to mesh. */
void rejectCrossingContours(const PreparedSlice& slice)
{
  const auto crossings = contourCrossings(slice.contours);
  if (crossings.empty())
    return;
  const ContourEdge& first = crossings.front().first;
  const ContourEdge& second = crossings.front().second;
  const Point2& where = slice.contours[first.contour][first.edge];
  std::ostringstream message;
  message << "contour stack: in the slice at z = " << slice.z << " mm, contour " << first.contour
          << (first.contour == second.contour ? " crosses or touches itself" : " crosses or touches contour " +
                                                                                  std::to_string(second.contour))
          << " near (" << where.x << ", " << where.y << ")";
  throw Error(message.str());
}

/** Each slice's contours cleaned, checked and nested, slices side by side (each on its own); a
 *  failure is reported for the lowest slice that fails, as one slice after another would. */
std::vector<PreparedSlice> prepareSlices(const ContourStack& stack, double tolerance, unsigned int threads)
{
  std::vector<PreparedSlice> slices(stack.slices.size());
  parallelFor(stack.slices.size(), threads, [&](std::size_t k)
  {
    slices[k].z = stack.slices[k].z;
    for (const Polygon2& contour : stack.slices[k].contours)
    {
      // A contour on one line has nothing inside: dropped. A figure eight has no area either, yet
      // is no sliver: it is kept for the crossing check, which rejects it.
      Polygon2 cleaned = cleanContour(contour, tolerance, false);
      if (!cleaned.empty() && !onOneLine(cleaned))
        slices[k].contours.push_back(std::move(cleaned));
    }
    rejectCrossingContours(slices[k]);
    slices[k].nesting = orientAndNest(slices[k].contours);
  });
  return slices;
}

double medianEdgeLength(const std::vector<PreparedSlice>& slices)
{
  std::vector<double> lengths;
  for (const PreparedSlice& slice : slices)
    appendEdgeLengths(slice.contours, lengths);
  return median(std::move(lengths), 1.0);
}

} // namespace

double mergeToleranceFor(const ContourStack& stack, double asked)
{
  // Ten steps: a rounded point's in-plane coordinates on a tilted plane are off by up to about one
  // step, two such points drawn at one place by up to two. Within a tolerance that close to their
  // difference, some pairs were merged and others not, and a slice kept two points its neighbour's
  // one point merged with (six decimals, planes tilted 2-15 degrees: 25 of 30 stacks refused). At two
  // decimals or fewer the points differ by far more than the tolerance asked and stay apart, as
  // points drawn apart do; a tolerance of 0.1 mm would join points a planner drew apart.
  const double fromRounding = 10.0 * stack.coordinateStep;
  return fromRounding <= 0.01 ? std::max(asked, fromRounding) : asked;
}

TriangleMesh reconstructSurface(const ContourStack& stack, const ReconstructionOptions& asked,
                                ReconstructionStatistics* statisticsOut)
{
  checkStack(stack);
  ReconstructionOptions options = asked;
  options.mergeTolerance = mergeToleranceFor(stack, asked.mergeTolerance);
  ReconstructionStatistics statistics;
  const unsigned int threads = threadCount(options.threads);
  std::vector<PreparedSlice> slices = prepareSlices(stack, options.mergeTolerance, threads);
  const std::size_t n = slices.size();
  bool anyContour = false;
  for (const PreparedSlice& slice : slices)
    anyContour = anyContour || !slice.contours.empty();
  if (!anyContour)
    throw Error("contour stack: no contour to mesh");

  // Short means: against the median contour edge as given, before crossing points shorten edges.
  const double medianEdgeBefore = medianEdgeLength(slices);
  // Adjacent slices must meet only at common vertices: a forward pass carries split points up the
  // stack, a backward pass carries them down along coincident walls.
  for (std::size_t k = 0; k + 1 < n; ++k)
    statistics.crossingPoints +=
      insertMutualIntersections(slices[k].contours, slices[k + 1].contours, options.mergeTolerance);
  for (std::size_t k = n - 1; k-- > 0;)
    statistics.crossingPoints +=
      insertMutualIntersections(slices[k].contours, slices[k + 1].contours, options.mergeTolerance);
  // A crossing point next to a contour vertex leaves a short contour edge; the vertex is shared by the
  // slabs on both sides, so it goes from the contour itself, before either slab is tiled.
  if (options.shortEdgeFraction > 0.0)
    for (std::size_t k = 0; k < n; ++k)
      statistics.verticesRemoved += removeVerticesNearCommonOnes(
        slices[k].contours, k > 0 ? &slices[k - 1].contours : nullptr, k + 1 < n ? &slices[k + 1].contours : nullptr,
        options.shortEdgeFraction * medianEdgeBefore, options.mergeTolerance);

  MeshBuilder mesh;
  for (PreparedSlice& slice : slices)
    for (const Polygon2& contour : slice.contours)
    {
      slice.firstVertexId.push_back(static_cast<std::int32_t>(mesh.addPoint(contour[0].x, contour[0].y, slice.z)));
      for (std::size_t i = 1; i < contour.size(); ++i)
        mesh.addPoint(contour[i].x, contour[i].y, slice.z);
    }

  SlabLiftOptions liftOptions;
  liftOptions.capPlacement = options.capPlacement;
  liftOptions.minAngleDegrees = options.minAngleDegrees;
  liftOptions.maxEdgeLength = options.maxEdgeLength;
  liftOptions.surfaceMetricFlips = !options.planarTiling;
  // The contours' median edge once they share their crossing points, but no less than half the one
  // before: where contours lie over each other on adjacent planes, their rounding crosses every few
  // micrometres, most edges become that short, and rows that close took all the memory there was.
  liftOptions.rowHeight = options.wallRowHeight > 0.0 ? options.wallRowHeight
                                                      : std::max(medianEdgeLength(slices), 0.5 * medianEdgeBefore);
  // The two automatic values that depend on the contours, not the grid: resolved here, reported.
  statistics.wallRowHeight = liftOptions.rowHeight;
  statistics.steinerSpacing = options.maxEdgeLength > 0.0 ? options.maxEdgeLength : liftOptions.rowHeight;

  // Slab k lies between slice k-1 and slice k; slabs 0 and n lie beyond the ends and only cap.
  auto zOf = [&](long k) {
    if (k < 0)
      return slices[0].z - (stack.sliceSpacing > 0.0 ? stack.sliceSpacing : slices[1].z - slices[0].z);
    if (k >= static_cast<long>(n))
      return slices[n - 1].z + (stack.sliceSpacing > 0.0 ? stack.sliceSpacing : slices[n - 1].z - slices[n - 2].z);
    return slices[k].z;
  };
  auto sliceOf = [&](long k) -> const PreparedSlice* {
    return k < 0 || k >= static_cast<long>(n) ? nullptr : &slices[k];
  };
  auto makeOverlay = [&](long k) {
    return std::make_unique<SlabOverlay>(sliceOf(k - 1), sliceOf(k), zOf(k - 1), zOf(k), options.mergeTolerance);
  };
  // A contour is isolated when its region meets neither neighbour slice.
  auto isolation = [](const std::vector<char>& below, const std::vector<char>& above) {
    std::vector<char> isolated(below.size());
    for (std::size_t c = 0; c < below.size(); ++c)
      isolated[c] = !below[c] && !above[c];
    return isolated;
  };

  // Slabs are independent once each slice knows whether its contours are isolated, which needs the
  // overlays on both sides: slabs go in batches, a batch's overlays built and its slabs tiled side by
  // side (each on its own builder), then appended in slab order. Only a batch's overlays are alive
  // at a time (their triangulations are most of the stage's memory).
  const long batch = threads > 1 ? 2 * static_cast<long>(threads) : 1;
  const long slabCount = static_cast<long>(n) + 1;
  std::vector<char> lowerIsolated; // of the slice below the batch's first slab
  std::unique_ptr<SlabOverlay> carried = makeOverlay(0);
  for (long k0 = 0; k0 < slabCount; k0 += batch)
  {
    const long k1 = std::min(k0 + batch, slabCount); // slabs [k0, k1); overlay k1 is needed too
    std::vector<std::unique_ptr<SlabOverlay>> overlays(static_cast<std::size_t>(k1 - k0 + 1));
    overlays[0] = std::move(carried);
    parallelFor(overlays.size() - 1, threads,
                [&](std::size_t i)
                {
                  const long k = k0 + 1 + static_cast<long>(i);
                  if (k <= static_cast<long>(n))
                    overlays[i + 1] = makeOverlay(k);
                });
    // isolated[i]: the slice above slab k0 + i (empty beyond the last slice).
    std::vector<std::vector<char>> isolated(overlays.size() - 1);
    for (std::size_t i = 0; i + 1 < overlays.size(); ++i)
      if (overlays[i + 1])
        isolated[i] = isolation(overlays[i]->upperContinues(), overlays[i + 1]->lowerContinues());
    std::vector<MeshBuilder> slabMeshes(isolated.size(), MeshBuilder(mesh.mesh()));
    std::vector<ReconstructionStatistics> slabStatistics(isolated.size());
    parallelFor(isolated.size(), threads,
                [&](std::size_t i)
                {
                  SlabLiftOptions slabOptions = liftOptions;
                  slabOptions.lowerIsolated = i == 0 ? &lowerIsolated : &isolated[i - 1];
                  slabOptions.upperIsolated = &isolated[i];
                  overlays[i]->lift(slabMeshes[i], slabOptions, slabStatistics[i]);
                  overlays[i].reset();
                });
    for (std::size_t i = 0; i < slabMeshes.size(); ++i)
    {
      slabMeshes[i].appendTo(mesh);
      statistics.steinerPoints += slabStatistics[i].steinerPoints;
      statistics.wallTriangles += slabStatistics[i].wallTriangles;
      statistics.capTriangles += slabStatistics[i].capTriangles;
      statistics.tilingTriangles += slabStatistics[i].tilingTriangles;
      ++statistics.slabs;
    }
    if (options.progress)
      options.progress(static_cast<double>(k1) / static_cast<double>(slabCount));
    lowerIsolated = std::move(isolated.back());
    carried = std::move(overlays.back());
  }

  if (statisticsOut)
    *statisticsOut = statistics;
  // Grown slab by slab: held through the finishing (its projection's reference) at its size.
  TriangleMesh tiling = mesh.release();
  tiling.points.shrink_to_fit();
  tiling.triangles.shrink_to_fit();
  return tiling;
}

} // namespace slicemesh

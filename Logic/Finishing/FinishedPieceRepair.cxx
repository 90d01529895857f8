#include "Finishing/FinishedPieceRepair.h"

#include "Finishing/CrossingPlaces.h"
#include "Finishing/CrossingRepair.h"
#include "Finishing/PieceRejection.h"
#include "Finishing/PutBackVertices.h"

#include <algorithm>

namespace slicemesh
{
namespace
{

/** More crossings than this and they are not repaired where they are (repairedLocally): a few folds
 *  are what flips and collapses undo (the thresholded Colin27 MRI's two large pieces had 3 and 14,
 *  natbrainlab's pieces at most 48), not sheets that pass through each other all along a gap. */
constexpr std::size_t mostCrossingsRepairedLocally = 64;

/** Narrower than this (degrees), a triangle left beside a repaired fold is widened if an operation
 *  can; the whole piece's narrow triangles are widened later (widenedNarrowTriangles). */
constexpr double besideRepairNarrowAngle = 20.0;

/** How many vertices are where `unsmoothed` has them. */
std::size_t verticesAt(const std::vector<Point3>& points, const std::vector<Point3>& unsmoothed)
{
  std::size_t at = 0;
  for (std::size_t v = 0; v < points.size(); ++v)
    at += samePoint(points[v], unsmoothed[v]);
  return at;
}

/** How many vertices that smoothing moved are where the remesh left them (`unsmoothed`). */
std::size_t verticesLeftUnsmoothed(const std::vector<Point3>& points, const std::vector<Point3>& smoothed,
                                   const std::vector<Point3>& unsmoothed)
{
  std::size_t left = 0;
  for (std::size_t v = 0; v < points.size(); ++v)
    left += !samePoint(smoothed[v], unsmoothed[v]) && samePoint(points[v], unsmoothed[v]);
  return left;
}

/** After a local repair: the vertices put back for the crossings it undid (the remesh's own folds,
 *  which no smoothing caused) take their `smoothed` places again, except where that makes triangles
 *  cross; if that leaves the piece invalid in any way, it stays as repaired. */
void resmoothedAfterRepair(TriangleMesh& mesh, const std::vector<Point3>& smoothed, const std::vector<Point3>& unsmoothed,
                           MeshValidation& validation, std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  const std::vector<Point3> repaired = mesh.points;
  const MeshValidation repairedValidation = validation;
  const std::vector<char> moved = movedVertices(repaired, smoothed);
  mesh.points = smoothed;
  validation = validateMeshAfterMovingPoints(mesh, validation, moved, crossings);
  unsmoothCrossings(mesh, unsmoothed, validation, crossings);
  if (!rejection(validation, repairedValidation).empty()) // as repaired, then
  {
    mesh.points = repaired;
    validation = repairedValidation;
    crossings.clear();
  }
}

/** The vertices a local repair may change: within two target edges of `places`, not held on a
 *  drawn contour. */
std::vector<char> repairableVertices(const TriangleMesh& mesh, const std::vector<Point3>& places,
                                     const std::vector<char>& held, const SurfaceFinishingOptions& options)
{
  std::vector<char> movable = verticesNear(mesh, places, 2.0 * keptRadius(options));
  if (!held.empty())
    for (std::size_t v = 0; v < movable.size(); ++v)
      movable[v] = movable[v] && !held[v];
  return movable;
}

} // namespace

bool repairableLocally(const MeshValidation& validation)
{
  return validation.selfIntersections > 0 && validation.selfIntersections <= mostCrossingsRepairedLocally &&
         validation.soundTopology() && validation.degenerateTriangles == 0;
}

std::size_t repairedLocally(TriangleMesh& mesh, MeshValidation& validation,
                            std::vector<std::pair<std::size_t, std::size_t>>& crossings, std::vector<Point3>& crossedAt,
                            const std::vector<char>& held, const SurfaceFinishingOptions& options,
                            std::vector<Point3>& unsmoothed, std::vector<Point3>& smoothed, bool resmooth,
                            std::size_t& unsmoothedVertices)
{
  const std::vector<Point3> places = crossingPlaces(mesh, crossings);
  // The repair starts from these pairs: only if they are every crossing the validation counted does
  // undoing them all leave none among the triangles it did not change.
  const bool everyCrossingListed = crossings.size() == validation.selfIntersections;
  std::vector<char> heldNow = held;
  const std::size_t atRemeshBefore = verticesAt(mesh.points, unsmoothed);
  const std::vector<char> movable = repairableVertices(mesh, places, held, options);
  const CrossingRepair repair = repairCrossingsLocally(mesh, crossings, movable, options.remeshing.targetEdgeLength);
  renumber(repair, unsmoothed, smoothed, heldNow);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (!samePoint(mesh.points[v], unsmoothed[v]) && !samePoint(mesh.points[v], smoothed[v])) // moved by the repair
      unsmoothed[v] = smoothed[v] = mesh.points[v];
  unsmoothedVertices -= atRemeshBefore - verticesAt(mesh.points, unsmoothed); // those collapsed
  // Not all undone: the piece is remeshed around the crossings left (crossedAt); the whole test of
  // a piece of a million triangles would only confirm them.
  if (!repair.undone)
  {
    crossedAt = crossingPlaces(mesh, repair.stillCrossing);
    crossings.clear();
    validation.selfIntersections = std::max<std::size_t>(1, repair.stillCrossing.size());
    return repair.operations();
  }
  // Every pair the repair undid had a triangle it changed: the triangles it left as they were cross
  // nothing among themselves, and those it changed, tested against the rest, give the whole test's
  // answer at the cost of the few that changed (the whole test of a piece of 1.5 million triangles
  // takes a second and holds a grid of about 100 bytes a triangle); the edges are gathered around
  // them only.
  MeshValidation leftAlone = validation;
  if (everyCrossingListed)
    leftAlone.selfIntersections = 0; // else validated whole
  validation = validateMeshAfterLocalChange(mesh, leftAlone, repair.changed, crossings);
  crossedAt = crossingPlaces(mesh, crossings);
  if (validation.selfIntersections > 0 || !resmooth)
    return repair.operations();
  resmoothedAfterRepair(mesh, smoothed, unsmoothed, validation, crossings);
  unsmoothedVertices = verticesLeftUnsmoothed(mesh.points, smoothed, unsmoothed);
  TriangleMesh widened = mesh;
  const std::vector<char> widenable = repairableVertices(widened, places, heldNow, options);
  const CrossingRepair widening =
    widenNarrowTrianglesLocally(widened, widenable, options.remeshing.targetEdgeLength, besideRepairNarrowAngle);
  if (widening.operations() == 0)
    return repair.operations();
  // The piece crossed nothing before: as above, around the triangles the widening changed.
  std::vector<std::pair<std::size_t, std::size_t>> widenedCrossings;
  MeshValidation widenedValidation = validateMeshAfterLocalChange(widened, validation, widening.changed, widenedCrossings);
  if (!rejection(widenedValidation, validation).empty()) // crossing a sheet the local test did not see
    return repair.operations();
  mesh = std::move(widened);
  validation = widenedValidation;
  crossings.clear();
  crossedAt.clear();
  renumber(widening, unsmoothed, smoothed);
  unsmoothedVertices = verticesLeftUnsmoothed(mesh.points, smoothed, unsmoothed);
  return repair.operations() + widening.operations();
}

} // namespace slicemesh

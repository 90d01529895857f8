#include "Finishing/SurfaceFinishing.h"

#include "Core/ParallelFor.h"
#include "Finishing/CrossingPlaces.h"
#include "Finishing/FinishedPieceRepair.h"
#include "Finishing/HeldContourEdges.h"
#include "Finishing/NarrowTriangleWidening.h"
#include "Finishing/PieceRejection.h"
#include "Finishing/PieceTargetVolumes.h"
#include "Finishing/PutBackVertices.h"
#include "Measures/ClosestPointGrid.h"
#include "Measures/ComponentOrientation.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshCrossings.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

namespace slicemesh
{
namespace
{

/** How far the vertices not held by drawn contours may move to give a piece its volume (mm): a
 *  quarter of the slice spacing; 0 (unbounded) without held contours. On drawn contours only the
 *  caps and the rows between the slices move, and a wall thinner than an edge has no more than a row
 *  of vertices along each cap, which would be pushed far past the half slice to make up its volume. */
double heldOffset(const SurfaceFinishingOptions& options)
{
  if (!options.heldContours)
    return 0.0;
  const ContourStack& stack = *options.heldContours;
  double spacing = stack.sliceSpacing;
  if (!(spacing > 0.0) && stack.slices.size() > 1)
    spacing = (stack.slices.back().z - stack.slices.front().z) / static_cast<double>(stack.slices.size() - 1);
  return spacing > 0.0 ? 0.25 * spacing : options.remeshing.targetEdgeLength;
}

/** A piece held on drawn contours that ends further than this from its volume (a fraction of it)
 *  is finished again without them. A thin wall's caps leave it a few percent short (a 2 mm shell
 *  1-3%, its caps a row of vertices each); a disc 2 mm across drawn in one slice, all caps, more
 *  than half. */
constexpr double heldVolumeShortfall = 0.1;

/** The vertices of `mesh` on the held contours (SurfaceFinishingOptions::heldContours), a flag per
 *  vertex; empty without held contours. */
std::vector<char> heldVertices(const TriangleMesh& mesh, const SurfaceFinishingOptions& options)
{
  return options.heldContours ? heldContourEdges(mesh, *options.heldContours).vertices : std::vector<char>();
}

} // namespace

SurfaceFinishingOptions finishingOptionsFor(const std::array<double, 3>& spacing)
{
  SurfaceFinishingOptions options;
  options.remeshing.targetEdgeLength = automaticEdgeLength(spacing);
  options.remeshing.gridSpacing = spacing;
  // A voxel's staircase is a fraction of its side deep along each axis: 1 mm slices of 0.5 mm pixels
  // leave steps twice as deep across the slices as within them. Away from sharp features the true
  // surface may lie anywhere within half a voxel of a terrace.
  for (int axis = 0; axis < 3; ++axis)
  {
    options.smoothing.maxDisplacement[axis] = 0.3 * spacing[axis];
    options.smoothing.maxDisplacementAwayFromFeatures[axis] = 0.5 * spacing[axis];
  }
  return options;
}

const char* finishName(SurfaceFinish finish)
{
  switch (finish)
  {
    case SurfaceFinish::Remeshed:
      return "Remeshed";
    case SurfaceFinish::Smoothed:
      return "Smoothed";
    case SurfaceFinish::Tiled:
      break;
  }
  return "Tiled";
}

namespace
{

/** Whether a piece (`tiled`, its validation) is a speck: its area under that of speckTargetTriangles
 *  equilateral triangles of the target edge (a cube of two voxels a side, about). Measured in the
 *  target's units, not in the tiling's triangles, whose size follows the contours' point spacing. */
constexpr double speckTargetTriangles = 48.0;

/** The area of an equilateral triangle of this edge. */
double equilateralArea(double edge)
{
  return 0.25 * std::sqrt(3.0) * edge * edge;
}

bool isSpeck(const MeshValidation& tiled, double targetEdgeLength)
{
  return tiled.area < speckTargetTriangles * equilateralArea(targetEdgeLength);
}

/** The edge a speck (`tiled`, its validation) is remeshed at: the one at which its area holds as
 *  many equilateral triangles as it was tiled with, the target edge at most. It gets about as many
 *  triangles as before, shaped by the remesh instead of by its contour points and slices; more
 *  would improve the angles little for the triangles they cost. */
double speckEdgeLength(const TriangleMesh& tiled, const MeshValidation& validation, double targetEdgeLength)
{
  const double triangles = static_cast<double>(tiled.triangles.size());
  return std::min(targetEdgeLength, std::sqrt(validation.area / triangles / equilateralArea(1.0)));
}

/** Where a piece is remeshed around: its tiled triangles within keptRadius of these places are kept
 *  as they are and the rest is remeshed (remeshSurfaceAround). */
struct KeptPlaces
{
  /** Where a remesh of the piece crossed itself (two sheets of it closer than the target edge): the
   *  tiled triangles kept there are smoothed with the rest, and put back only where that crosses. */
  std::vector<Point3> crossedItself;
  /** Where the finished piece crossed another piece: the tiled triangles kept there stay as tiled,
   *  unsmoothed. The other piece keeps its own there too, and the tiling keeps the two apart; the
   *  other piece is not at hand while this one is finished, so a crossing would not be seen. */
  std::vector<Point3> crossedOthers;

  std::vector<Point3> all() const
  {
    std::vector<Point3> places = crossedItself;
    places.insert(places.end(), crossedOthers.begin(), crossedOthers.end());
    return places;
  }
};

/** One connected piece of the tiling, finished as far as it stays a valid surface of its own
 *  topology: remeshed and smoothed, else smoothed, else as it was tiled. */
struct FinishedPiece
{
  TriangleMesh mesh;
  SurfaceFinish finish = SurfaceFinish::Tiled;
  std::string why; ///< why less than asked was applied
  std::size_t unsmoothedVertices = 0;
  MeshValidation validation; ///< of `mesh`
  std::size_t trianglesKeptTiled = 0; ///< of a remeshed piece: tiled triangles kept around `kept`
  /** Of a piece remeshed around places: those places. Remeshed again, it keeps them and adds new ones. */
  KeptPlaces kept;
  /** Where `mesh` crosses itself, from its validation: the centroids of the triangles of every
   *  crossing pair (none in a valid piece). */
  std::vector<Point3> crossedAt;
  std::size_t crossingRepairOperations = 0; ///< of the repair that undid its crossings (repairedLocally)
  std::size_t narrowTrianglesWidened = 0;   ///< operations that widened its narrow triangles at the end
  /** Whether it crossed another piece once already: laid onto its tiled surface there (or remeshed
   *  around those places after that failed). */
  bool laidBack = false;
};

/** The validation of a piece of the tiling as it was tiled, without its self-intersection test:
 *  when the whole tiling was checked (and had none) the piece has none either; otherwise the test is
 *  run only if the piece is kept as tiled (complete). */
MeshValidation asTiled(const TriangleMesh& piece, bool tilingChecked)
{
  MeshValidation v = validateMeshTopology(piece);
  v.selfIntersectionChecked = tilingChecked;
  return v;
}

/** The validation `v` of `mesh`, with its self-intersection test run if it was not. */
MeshValidation complete(const TriangleMesh& mesh, const MeshValidation& v)
{
  return v.selfIntersectionChecked ? v : validateMesh(mesh);
}

FinishedPiece keptAsTiled(const TriangleMesh& piece, const MeshValidation& tiled, SurfaceFinish finish, std::string why)
{
  return { piece, finish, std::move(why), 0, complete(piece, tiled) };
}

/** Vertices put back where they were before the smoothing (where two sheets met) undo its
 *  relaxation around them too, and their triangles are the narrow ones it was for. Relaxed again
 *  with those vertices kept (and, where that makes sheets meet, without the relaxation there), the
 *  piece is kept so only if it crosses itself nowhere; `validation` (no crossings) is then the new
 *  piece's. */
void relaxBesidePutBack(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed, MeshValidation& validation,
                        const SurfaceFinishingOptions& options, unsigned int threads)
{
  std::vector<char> putBack(mesh.points.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    putBack[v] = samePoint(mesh.points[v], unsmoothed[v]);
  TriangleMesh relaxed = mesh;
  if (!relaxNarrowTriangles(relaxed, unsmoothed, putBack, options.smoothing, threads))
    return; // nothing narrow beside them: the piece as it is, already validated
  // The piece as it was had no crossings (validation): only the relaxed vertices' triangles are tested.
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  MeshValidation after =
    validateMeshAfterMovingPoints(relaxed, validation, movedVertices(mesh.points, relaxed.points), crossings);
  // Where the relaxation made sheets meet, its vertices go back to where they were before it.
  unsmoothCrossings(relaxed, mesh.points, after, crossings);
  if (after.selfIntersections == 0 && rejection(after, validation).empty())
  {
    mesh = std::move(relaxed);
    validation = after;
  }
}

/** More crossings than this and a piece is not remeshed around them: a few thin gaps are what the
 *  second remesh is for, not a piece that is gaps throughout. */
constexpr std::size_t mostCrossingsRemeshedAround = 500;

/** Whether a remesh rejected for crossing itself is worth remeshing again around the crossings. */
bool crossesItselfInAFewPlaces(const MeshValidation& v)
{
  return v.selfIntersections > 0 && v.selfIntersections <= mostCrossingsRemeshedAround;
}

/** A remeshed piece smoothed, given its volume, and put back where smoothing made it cross; its
 *  vertices within keptRadius of `crossedOthers` (KeptPlaces: there its remesh kept the tiled
 *  triangles) are put back where the remesh left them, as tiled. */
FinishedPiece smoothedRemesh(TriangleMesh remeshed, const SurfaceFinishingOptions& options, double volume,
                             unsigned int threads, const std::vector<Point3>& crossedOthers = {})
{
  const std::vector<char> leftAsTiled =
    crossedOthers.empty() ? std::vector<char>() : verticesNear(remeshed, crossedOthers, keptRadius(options));
  const std::vector<char> held = heldVertices(remeshed, options);
  std::vector<Point3> unsmoothed; // smoothing moves points only
  smoothSurface(remeshed, options.smoothing, threads, held, &unsmoothed);
  // The remesh's chords cut the corners of structures a few edges across: the piece gets its volume
  // back (on drawn contours, as far as heldOffset lets it).
  offsetToVolume(remeshed, volume, held, heldOffset(options), threads);
  // After the offset, which would move them too (outwards: towards the other piece).
  std::size_t unsmoothedVertices = leftAsTiled.empty() ? 0 : unsmooth(remeshed, unsmoothed, leftAsTiled);
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  MeshValidation validation = validateMesh(remeshed, crossings);
  std::vector<Point3> smoothed = validation.selfIntersections > 0 ? remeshed.points : std::vector<Point3>();
  unsmoothedVertices += unsmoothCrossings(remeshed, unsmoothed, validation, crossings);
  std::vector<Point3> crossedAt = crossingPlaces(remeshed, crossings);
  // What putting vertices back did not undo is the remesh's own: a chord through the other sheet of
  // a gap a voxel wide, or a fold where two voxels touch along an edge. A few such crossings are
  // undone where they are; else the piece is remeshed again around them (remeshedPiece).
  std::size_t repairs = 0;
  if (repairableLocally(validation))
  {
    repairs = repairedLocally(remeshed, validation, crossings, crossedAt, held, options, unsmoothed, smoothed,
                              leftAsTiled.empty(), unsmoothedVertices);
  }
  if (unsmoothedVertices > 0 && validation.selfIntersections == 0)
    relaxBesidePutBack(remeshed, unsmoothed, validation, options, threads);
  // Last, on the valid piece: its narrow triangles where a structure is as thin as an edge. The
  // vertices on drawn contours and those left as tiled beside another piece stay, found again on the
  // piece as it is now: a local repair above renumbers its vertices (and the widening does too, so
  // no per-vertex array above is used past here).
  std::vector<char> fixed = heldVertices(remeshed, options);
  if (!crossedOthers.empty())
  {
    const std::vector<char> asTiled = verticesNear(remeshed, crossedOthers, keptRadius(options));
    fixed.resize(remeshed.points.size(), 0);
    for (std::size_t v = 0; v < fixed.size(); ++v)
      fixed[v] = fixed[v] || asTiled[v];
  }
  const std::size_t widenings = widenNarrowTriangles(remeshed, validation, fixed, options.remeshing.targetEdgeLength);
  FinishedPiece piece{ std::move(remeshed), SurfaceFinish::Remeshed, {}, unsmoothedVertices, validation, 0, {},
                       std::move(crossedAt) };
  piece.crossingRepairOperations = repairs;
  piece.narrowTrianglesWidened = widenings;
  return piece;
}

/** The piece remeshed around `places` (KeptPlaces) and smoothed. Each new remesh can cross itself
 *  elsewhere (its triangles differ everywhere): those places are added and it is tried again, three
 *  tries in all. The first that is a valid surface of the tiled piece's topology (`reference`), with
 *  the places it was remeshed around; else nothing. */
std::optional<FinishedPiece> remeshedAround(const TriangleMesh& tiled, const MeshValidation& reference,
                                            const SurfaceFinishingOptions& options, double volume, unsigned int threads,
                                            KeptPlaces places)
{
  for (int attempt = 0; attempt < 3; ++attempt)
  {
    const std::vector<char> keep = trianglesNear(tiled, places.all(), keptRadius(options));
    std::optional<FinishedPiece> around;
    try
    {
      around = smoothedRemesh(remeshSurfaceAround(tiled, keep, options.remeshing, threads, options.heldContours.get()),
                              options, volume, threads, places.crossedOthers);
    }
    catch (const std::exception&) // the triangles around the kept ones are no manifold surface
    {
      return std::nullopt;
    }
    if (rejection(around->validation, reference).empty())
    {
      around->trianglesKeptTiled = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));
      around->kept = std::move(places);
      return around;
    }
    if (!crossesItselfInAFewPlaces(around->validation))
      return std::nullopt;
    const std::vector<Point3>& more = around->crossedAt;
    places.crossedItself.insert(places.crossedItself.end(), more.begin(), more.end());
  }
  return std::nullopt;
}

/** The remeshed, smoothed piece, if it is a valid surface of the tiled piece's topology (`reference`);
 *  else nothing, and `why` says what was wrong. Where two sheets are closer than the target edge (a
 *  thin gap between gyri, a wall a voxel thick) the remesh's chords can pass through the other sheet:
 *  the piece is then remeshed again around those places (remeshedAround). */
std::optional<FinishedPiece> remeshedPiece(const TriangleMesh& tiled, const MeshValidation& reference,
                                           const SurfaceFinishingOptions& options, double volume, unsigned int threads,
                                           std::string& why)
{
  // Remeshed first, then smoothed: the umbrella operator is a fair Laplacian only on a regular
  // mesh. Smoothing the tiling's rows (edges of every length and direction) first, then
  // remeshing, left the surface 10-20% farther from the true one on the benchmark's phantoms.
  std::optional<FinishedPiece> piece;
  try
  {
    piece = smoothedRemesh(remeshSurface(tiled, options.remeshing, threads, options.heldContours.get()), options, volume,
                           threads);
  }
  catch (const std::exception& e) // ours, or a CGAL precondition the piece does not meet
  {
    why = e.what();
    return std::nullopt;
  }
  why = rejection(piece->validation, reference);
  if (why.empty())
    return piece;
  if (!crossesItselfInAFewPlaces(piece->validation))
    return std::nullopt;
  KeptPlaces places{ std::move(piece->crossedAt), {} };
  piece.reset(); // not held beside the second remesh
  return remeshedAround(tiled, reference, options, volume, threads, std::move(places));
}

/** The options for one piece: with a grid spacing (SurfaceRemeshingOptions::gridSpacing), the target
 *  edge scaled by how the piece faces the grid, so that every piece, whatever its shape, stays
 *  under the triangles flying edges makes of it by the same margin. */
SurfaceFinishingOptions optionsForPiece(const SurfaceFinishingOptions& options, const TriangleMesh& tiled)
{
  const std::array<double, 3>& grid = options.remeshing.gridSpacing;
  if (!(grid[0] > 0.0 && grid[1] > 0.0 && grid[2] > 0.0))
    return options;
  const double facing = facingEdgeLength(tiled, grid);
  SurfaceFinishingOptions piece = options;
  if (facing > 0.0)
    piece.remeshing.targetEdgeLength *= facing / voxelFaceEdgeLength(grid);
  return piece;
}

/** `reference`: the piece's validation as tiled (asTiled); `volumeScale`: its finished volume over
 *  its tiled one; `threads`: for the work inside the piece. */
FinishedPiece finishPiece(const TriangleMesh& tiled, const MeshValidation& reference, const SurfaceFinishingOptions& asked,
                          double volumeScale, unsigned int threads)
{
  const SurfaceFinishingOptions options = optionsForPiece(asked, tiled);
  // The tiled piece is copied only if it is what is kept: a copy held through the remesh would
  // add a piece's worth to the run's peak memory.
  FinishedPiece result{ {}, SurfaceFinish::Tiled, {}, 0, {} };
  if (options.finish == SurfaceFinish::Remeshed)
  {
    // At the asked edge length, around what it crosses if it does. (A second attempt at half the
    // length, where a gap narrower than the edge makes the remesh cross itself, rescued the large
    // pieces of noisy k-means labels but cost 80 s and 1.4 million triangles there: not what was asked.)
    std::string why;
    const double volume = volumeScale * reference.volume;
    std::optional<FinishedPiece> remeshed = remeshedPiece(tiled, reference, options, volume, threads, why);
    if (remeshed && options.heldContours && std::abs(remeshed->validation.volume - volume) > heldVolumeShortfall * std::abs(volume))
    {
      // Held on its contours it cannot hold its volume (a structure a few millimetres across in one
      // slice, whose caps are most of it): finished as a mask's surface is, its contours not held.
      SurfaceFinishingOptions free = options;
      free.heldContours.reset();
      remeshed.reset();
      remeshed = remeshedPiece(tiled, reference, free, volume, threads, why);
    }
    if (remeshed)
      return std::move(*remeshed);
    result.why = "remeshed: " + why;
  }
  TriangleMesh smoothed = tiled;
  const std::vector<char> held = heldVertices(tiled, options);
  smoothSurface(smoothed, options.smoothing, threads, held);
  if (volumeScale != 1.0 && options.smoothing.iterations > 0) // no iterations asked: the tiling itself
    offsetToVolume(smoothed, volumeScale * reference.volume, held, heldOffset(options), threads);
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  MeshValidation validation = validateMesh(smoothed, crossings);
  const std::size_t unsmoothedVertices = unsmoothCrossings(smoothed, tiled.points, validation, crossings);
  const std::string why = rejection(validation, reference);
  if (why.empty())
  {
    result.mesh = std::move(smoothed);
    result.finish = SurfaceFinish::Smoothed;
    result.unsmoothedVertices = unsmoothedVertices;
    result.validation = validation;
    return result;
  }
  result.why += (result.why.empty() ? "" : "; ") + std::string("smoothed: ") + why;
  smoothed = TriangleMesh();
  result.mesh = tiled;
  result.validation = complete(tiled, reference);
  return result;
}

/** A speck (isSpeck), finished at its own scale: at the target edge remeshing or smoothing can only
 *  collapse a shape a couple of edges across, while as tiled its triangles follow its contour points
 *  and slices, not its shape. Remeshed at speckEdgeLength and smoothed like any piece, within the
 *  same bound on each vertex's move (a fraction of the voxel), and given its volume back; kept only
 *  if it is a valid surface of its tiled topology, else left as tiled (finish Tiled), which counts as
 *  finished. Only when a remesh is asked: smoothing alone leaves the tiling's triangles as they are. */
FinishedPiece finishedSpeck(const TriangleMesh& tiled, const MeshValidation& reference,
                            const SurfaceFinishingOptions& options, double volumeScale, unsigned int threads)
{
  if (options.finish == SurfaceFinish::Remeshed)
  {
    SurfaceFinishingOptions ownScale = options;
    // A speck's contours are not held: its caps are most of it, too few vertices to give it its
    // volume (a disc 2 mm across in one slice is tiled at under half its slab) if its contour stays.
    ownScale.heldContours.reset();
    ownScale.remeshing.targetEdgeLength = speckEdgeLength(tiled, reference, options.remeshing.targetEdgeLength);
    ownScale.remeshing.projectEachRound = true;
    std::string why;
    if (std::optional<FinishedPiece> remeshed =
          remeshedPiece(tiled, reference, ownScale, volumeScale * reference.volume, threads, why))
      return std::move(*remeshed);
  }
  return keptAsTiled(tiled, reference, SurfaceFinish::Tiled, {});
}

/** Rounds in which the pieces that cross other pieces once finished are laid onto their tiled
 *  surface where they cross (the first), then remeshed again around those places (three more),
 *  before those still crossing go back to their tiled shape. */
constexpr int roundsRemeshedAround = 4;

/** Rounds, after those, in which the pieces still crossing go back to their tiled shape. A valid
 *  tiling's pieces do not cross, so one round does it; pieces of a tiling that crosses itself (its
 *  self-intersections not tested yet) may still cross after them. */
constexpr int roundsPutBack = 8;

/** The pairs of triangles of different pieces that cross each other, as the pieces are finished now. */
std::vector<TrianglePair> piecesCrossing(const std::vector<FinishedPiece>& pieces, unsigned int threads)
{
  std::vector<const TriangleMesh*> meshes;
  for (const FinishedPiece& piece : pieces)
    meshes.push_back(&piece.mesh);
  return crossingTriangles(meshes, threads);
}

/** Where each piece in a crossing pair crosses: the centroids of both triangles of each of its pairs
 *  (the other piece's triangle is where this one must not reach), by piece in increasing order. */
std::map<std::size_t, std::vector<Point3>> crossingPlacesByPiece(const std::vector<FinishedPiece>& pieces,
                                                                 const std::vector<TrianglePair>& crossing)
{
  std::map<std::size_t, std::vector<Point3>> places;
  for (const auto& [a, b] : crossing)
  {
    const Point3 at[2] = { centroid(pieces[a.mesh].mesh, a.triangle), centroid(pieces[b.mesh].mesh, b.triangle) };
    for (const std::size_t p : { a.mesh, b.mesh })
      places[p].insert(places[p].end(), std::begin(at), std::end(at));
  }
  return places;
}

/** A remeshed piece that crossed another one at `places`, its vertices within `radius` of them laid
 *  onto its tiled surface (the closest point), where the remesh had put them before the smoothing
 *  and the volume offset moved them towards the other piece, whose tiled surface a valid tiling
 *  keeps apart; the piece's other vertices then give it its `volume` back, as after the first
 *  smoothing. Whether the piece is still a valid surface of its tiled topology (`reference`); else
 *  it is left as it was. Whether it still crosses the other piece, the next round tells. On a brain
 *  atlas whose labels come in thousands of pieces, each large piece beside a one-voxel speck was
 *  remeshed whole again for it. */
bool laidOntoTiled(FinishedPiece& piece, const TriangleMesh& tiled, const MeshValidation& reference,
                   const std::vector<Point3>& places, const SurfaceFinishingOptions& options, double volume,
                   unsigned int threads)
{
  const std::vector<char> near = verticesNear(piece.mesh, places, keptRadius(options));
  const std::vector<Point3> before = piece.mesh.points;
  const ClosestPointGrid onTiled(tiled);
  // Vertices on drawn contours were never smoothed: they stay, and so stay held for the widening.
  const std::vector<char> held = heldVertices(piece.mesh, options);
  std::vector<char> fixed = held;
  fixed.resize(near.size(), 0);
  std::size_t laid = 0;
  for (std::size_t v = 0; v < near.size(); ++v)
    if (near[v] && !fixed[v])
    {
      Point3& p = piece.mesh.points[v];
      const ClosestPointGrid::Point q = onTiled.closestPoint(ClosestPointGrid::Point(p.x, p.y, p.z));
      p = Point3{ q.x(), q.y(), q.z() };
      fixed[v] = 1;
      ++laid;
    }
  offsetToVolume(piece.mesh, volume, fixed, heldOffset(options), threads);
  const MeshValidation validation = validateMesh(piece.mesh);
  if (!rejection(validation, reference).empty())
  {
    piece.mesh.points = before;
    return false;
  }
  piece.validation = validation;
  piece.unsmoothedVertices += laid;
  // Laid back, a remesh's triangles can be narrow again where the tiling bends.
  piece.narrowTrianglesWidened +=
    widenNarrowTriangles(piece.mesh, piece.validation, held, options.remeshing.targetEdgeLength);
  return true;
}

/** A finished piece that crossed another one at `places`, finished again: if it was remeshed and
 *  `remeshAgain`, the first time laid onto its tiled surface there (laidOntoTiled), after that
 *  remeshed around those places besides the ones it was remeshed around already
 *  (KeptPlaces::crossedOthers); if that gives no valid surface, or else, put back to its tiled shape,
 *  which a valid tiling keeps apart from the other pieces. (A piece smoothed only could not be
 *  remeshed at all: around a few more places would not change that.) `tiled` and `reference`: the
 *  piece as tiled and its validation. */
FinishedPiece finishedAgainAround(FinishedPiece piece, const TriangleMesh& tiled, const MeshValidation& reference,
                                  const SurfaceFinishingOptions& asked, double volume, unsigned int threads,
                                  const std::vector<Point3>& places, bool remeshAgain)
{
  const SurfaceFinishingOptions options = optionsForPiece(asked, tiled);
  if (remeshAgain && piece.finish == SurfaceFinish::Remeshed && !piece.laidBack)
  {
    piece.laidBack = true;
    if (laidOntoTiled(piece, tiled, reference, places, options, volume, threads))
      return piece;
  }
  if (remeshAgain && piece.finish == SurfaceFinish::Remeshed)
  {
    KeptPlaces around = std::move(piece.kept);
    around.crossedOthers.insert(around.crossedOthers.end(), places.begin(), places.end());
    piece = FinishedPiece(); // not held beside the new remesh
    std::optional<FinishedPiece> again = remeshedAround(tiled, reference, options, volume, threads, std::move(around));
    if (again)
    {
      again->laidBack = true;
      return std::move(*again);
    }
  }
  return keptAsTiled(tiled, reference, SurfaceFinish::Tiled, "it crossed another piece once finished");
}

/** Pieces finished apart may meet (two pieces a voxel apart, each smoothed towards the other). Round
 *  after round, every piece that crosses another, unless it is left as tiled (in its tiled shape
 *  already), is finished again by `finishAgain(p, places, round)` (places: where it crosses,
 *  crossingPlacesByPiece), side by side on `threads` threads, until none cross or the rounds are
 *  over. Specks (`speck`) that cross go first, in a pass of their own that counts as no round (each
 *  finished again at its tiled volume, then back to its tiled shape): a speck is not worth another
 *  remesh of a large piece.
 *  Returns how many pairs of triangles of different pieces still cross. */
template <typename FinishAgain>
std::size_t separatePieces(std::vector<FinishedPiece>& pieces, const std::vector<char>& speck, unsigned int threads,
                           FinishAgain&& finishAgain)
{
  for (int round = 0;;)
  {
    const auto crossing = piecesCrossing(pieces, threads);
    std::vector<std::size_t> crossed, crossedSpecks;
    std::vector<std::vector<Point3>> places, speckPlaces;
    for (auto& [p, at] : crossingPlacesByPiece(pieces, crossing))
      if (pieces[p].finish != SurfaceFinish::Tiled)
      {
        (speck[p] ? crossedSpecks : crossed).push_back(p);
        (speck[p] ? speckPlaces : places).push_back(std::move(at));
      }
    const bool specksFirst = !crossedSpecks.empty();
    if (specksFirst)
    {
      crossed = std::move(crossedSpecks);
      places = std::move(speckPlaces);
    }
    else if (crossed.empty() || round == roundsRemeshedAround + roundsPutBack)
      return crossing.size();
    // Each piece into its own slot: the result does not depend on the number of threads.
    parallelFor(crossed.size(), threads, [&](std::size_t i) { finishAgain(crossed[i], places[i], round); });
    if (!specksFirst)
      ++round;
  }
}

/** The pieces' meshes side by side in one mesh; `firstTriangle[i]` is where piece i's triangles start. */
TriangleMesh joinPieces(const std::vector<FinishedPiece>& pieces, std::vector<std::size_t>& firstTriangle)
{
  std::vector<const TriangleMesh*> meshes;
  for (const FinishedPiece& piece : pieces)
    meshes.push_back(&piece.mesh);
  return joinMeshes(meshes, &firstTriangle);
}

} // namespace

FinishedSurface finishSurface(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                              const SurfaceFinishingOptions& options, unsigned int threads, double targetVolume,
                              const std::vector<ContourVolume>& targetShares)
{
  // The tiling's self-intersections may not have been looked for yet (MeshedContours): it is
  // checked here where it is handed back, and piece by piece where a piece is kept as tiled.
  // The tiling is copied into the result only where it is handed back: a copy held through the
  // finishing would add a tiling's worth to the run's peak memory.
  FinishedSurface result{ {}, tilingValidation, SurfaceFinish::Tiled, {} };
  if (options.finish == SurfaceFinish::Tiled)
  {
    result.mesh = tiling;
    result.validation = complete(tiling, tilingValidation);
    return result;
  }
  if (!tilingValidation.soundTopology() || (tilingValidation.selfIntersectionChecked && tilingValidation.selfIntersections > 0))
  {
    result.mesh = tiling;
    result.validation = complete(tiling, tilingValidation);
    result.fallback = "the tiling is not a valid surface, so it is not finished";
    return result;
  }

  // Piece by piece: one speck that cannot be remeshed must not cost the rest of the surface its
  // finish (a k-means label has thousands of pieces).
  // The pieces are independent: finished side by side, each into its own slot.
  // A tiling of one piece (the usual case) is its own piece: no copy of it is held.
  std::size_t components = 0;
  vertexComponents(tiling, components);
  const bool onePiece = components == 1 && !tiling.triangles.empty();
  // Each piece gets its own voxels' volume, whatever its tiling's shortfall: a structure in one slice
  // a few millimetres across is tiled at about half of its slab's volume. With several pieces, a
  // piece's target is the shares of its own contours (without shares, the target in proportion to
  // the tiled volumes), so a piece's volume does not depend on what else the label holds. A speck
  // follows its target only as far as half again its tiled volume (or a third less): a voxel is
  // tiled at a sixth of its volume (its domed caps are most of it), and an offset that gave all of
  // that back would bend it out of shape (given twice its tiled volume, a voxel of 0.5 x 0.5 x 2 mm
  // has a tenth of its triangles under 30 degrees). No piece makes up for another: shared in
  // proportion, a cube beside twenty single voxels was finished 1.7% too large.
  const double scale = targetVolume > 0.0 ? targetVolume / tilingValidation.volume : 1.0;
  auto followed = [](double s) { return std::clamp(s, 1.0 / 1.5, 1.5); };
  std::vector<TriangleMesh> split = onePiece ? std::vector<TriangleMesh>() : splitIntoPieces(tiling);
  std::vector<const TriangleMesh*> tiledPieces;
  if (onePiece)
    tiledPieces.push_back(&tiling);
  for (const TriangleMesh& piece : split)
    tiledPieces.push_back(&piece);
  std::vector<FinishedPiece> pieces(tiledPieces.size());
  std::vector<MeshValidation> tiledValidations(tiledPieces.size());
  std::vector<char> speck(tiledPieces.size());
  const std::vector<double> targets = !onePiece && targetVolume > 0.0 && !targetShares.empty()
                                        ? pieceTargetVolumes(tiledPieces, targetShares, targetVolume)
                                        : std::vector<double>();
  std::vector<double> volumeScales(tiledPieces.size(), 1.0);
  // Largest pieces first, each with every thread for the work inside it. A piece's own loops borrow
  // only threads that are idle (Core/WorkerPool.h): while the other pieces keep every thread busy
  // each piece runs on its own, and the last large one gets the threads as the others finish. (With
  // the threads only for a piece of over half the surface, a thresholded T1 brain's largest piece, a
  // third of the surface, was finished on one thread for 14 of the 55 s while the other waited.)
  std::vector<std::size_t> largestFirst(tiledPieces.size());
  std::iota(largestFirst.begin(), largestFirst.end(), std::size_t{ 0 });
  std::stable_sort(largestFirst.begin(), largestFirst.end(), [&](std::size_t a, std::size_t b)
                   { return tiledPieces[a]->triangles.size() > tiledPieces[b]->triangles.size(); });
  parallelFor(tiledPieces.size(), threads,
              [&](std::size_t i)
              {
                const std::size_t p = largestFirst[i];
                // A tiling of one piece is its own piece: its validation is the tiling's, not measured again.
                tiledValidations[p] = onePiece ? tilingValidation
                                               : asTiled(*tiledPieces[p], tilingValidation.selfIntersectionChecked);
                // A speck of a few voxels is a couple of target edges across: it is finished at its
                // own scale.
                speck[p] = isSpeck(tiledValidations[p], options.remeshing.targetEdgeLength);
                // A hole's piece and its shares are both negative.
                const double own = targets.empty() ? scale : targets[p] / tiledValidations[p].volume;
                volumeScales[p] = !(own > 0.0) ? 1.0 : speck[p] ? followed(own) : own;
                if (speck[p])
                  pieces[p] = finishedSpeck(*tiledPieces[p], tiledValidations[p], options, volumeScales[p], threads);
                else
                  pieces[p] = finishPiece(*tiledPieces[p], tiledValidations[p], options, volumeScales[p], threads);
              });

  // Pieces that cross each other once finished are laid onto their tiled surface where they cross,
  // then, if they still cross, remeshed again with their tiled triangles kept around those places,
  // as a piece whose remesh crosses itself is (pieces of one label a voxel apart are two sheets of
  // one structure), and checked again; those still crossing after roundsRemeshedAround rounds go
  // back to their tiled shape.
  const std::size_t crossingTriangles = separatePieces(
    pieces, speck, threads,
    [&](std::size_t p, const std::vector<Point3>& places, int round)
    {
      if (speck[p])
      {
        // Given back its volume it may reach a piece a voxel away: first without that, then as tiled.
        if (volumeScales[p] != 1.0)
        {
          volumeScales[p] = 1.0;
          pieces[p] = finishedSpeck(*tiledPieces[p], tiledValidations[p], options, 1.0, threads);
        }
        else
          pieces[p] = keptAsTiled(*tiledPieces[p], tiledValidations[p], SurfaceFinish::Tiled, {});
        return;
      }
      pieces[p] = finishedAgainAround(std::move(pieces[p]), *tiledPieces[p], tiledValidations[p], options,
                                      volumeScales[p] * tiledValidations[p].volume, threads, places,
                                      round < roundsRemeshedAround);
    });
  std::vector<MeshValidation> validations;
  std::vector<const TriangleMesh*> finishedPieces;
  std::vector<double> volumes;
  for (const FinishedPiece& piece : pieces)
  {
    validations.push_back(piece.validation);
    finishedPieces.push_back(&piece.mesh);
    volumes.push_back(piece.validation.volume);
  }
  MeshValidation validation = joinedValidation(validations, crossingTriangles);
  // Each piece faces as its tiled self did; whether that is right depends on which piece lies inside which.
  validation.misorientedComponents = misorientedComponents(finishedPieces, volumes, threads);
  split = {}; // no longer needed: not held beside the joined copy of the pieces
  std::vector<std::size_t> firstTriangle;
  TriangleMesh joined = joinPieces(pieces, firstTriangle);
  if (!validation.valid() || validation.components != tilingValidation.components ||
      validation.eulerCharacteristic != tilingValidation.eulerCharacteristic)
  {
    result.mesh = tiling;
    result.validation = complete(tiling, tilingValidation);
    result.fallback = "the finished pieces do not make a valid surface together (" + validation.summary() +
                      "), so the tiling is written";
    result.piecesByFinish[static_cast<std::size_t>(SurfaceFinish::Tiled)] = pieces.size();
    return result;
  }

  result.mesh = std::move(joined);
  result.validation = validation;
  result.finish = options.finish;
  std::size_t short_ = 0;
  std::string firstReason;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const FinishedPiece& piece = pieces[p];
    ++result.piecesByFinish[static_cast<std::size_t>(piece.finish)];
    result.unsmoothedVertices += piece.unsmoothedVertices;
    result.trianglesKeptTiled += piece.trianglesKeptTiled;
    result.crossingRepairOperations += piece.crossingRepairOperations;
    result.narrowTrianglesWidened += piece.narrowTrianglesWidened;
    if (speck[p])
    {
      // A speck left as tiled counts as finished as asked.
      ++(piece.finish == SurfaceFinish::Tiled ? result.smallPiecesAsTiled : result.smallPiecesRemeshed);
      continue;
    }
    result.finish = std::max(result.finish, piece.finish); // the enum runs from most to least finished
    if (piece.finish != options.finish)
    {
      ++short_;
      if (firstReason.empty())
        firstReason = piece.why;
    }
  }
  if (short_ > 0)
  {
    result.fallback = std::to_string(short_) + " of " + std::to_string(pieces.size()) + " pieces were finished less than asked (" +
                      std::to_string(pieces.size() - short_) + " as asked); the first: " + firstReason;
  }
  return result;
}

} // namespace slicemesh

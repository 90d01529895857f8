// The finishing stage after the tiling: 3D smoothing and isotropic remeshing, kept only when the
// result is still a valid surface of the same topology.
#ifndef SurfaceFinishing_h
#define SurfaceFinishing_h

#include "Measures/ContourVolumes.h"
#include "Measures/MeshValidation.h"
#include "Finishing/SurfaceRemeshing.h"
#include "Finishing/SurfaceSmoothing.h"

#include <array>
#include <memory>
#include <string>

namespace slicemesh
{

/** How far the tiling is finished. */
enum class SurfaceFinish
{
  Remeshed, ///< remeshed to the target edge length, then smoothed in 3D (the default)
  Smoothed, ///< smoothed in 3D; the tiling's triangles kept
  Tiled     ///< the tiling as it is (the paper's surface: contour vertices stay on their slices)
};

struct SurfaceFinishingOptions
{
  SurfaceFinish finish = SurfaceFinish::Remeshed;
  SurfaceSmoothingOptions smoothing;
  SurfaceRemeshingOptions remeshing;
  /** Drawn contours the finished surface passes through (a structure set's, in the tiling's frame;
   *  none for a mask, whose traced contours are a staircase to smooth away). The tiling's edges
   *  along them (HeldContourEdges.h) are kept by the remesh, and their vertices by the smoothing and
   *  the volume offset: only the surface between the slices and the caps is finished. */
  std::shared_ptr<const ContourStack> heldContours;
};

struct FinishedSurface
{
  TriangleMesh mesh;
  MeshValidation validation; ///< of `mesh`
  /** What was applied: the least finished of the connected pieces (less than asked after a
   *  fallback, however many of the pieces it concerns: `fallback` counts them). */
  SurfaceFinish finish = SurfaceFinish::Tiled;
  std::string fallback; ///< why less was applied than asked, and to how many pieces; empty when all of it was
  /** Vertices left unsmoothed (where the remesh put them, or the tiling for a piece smoothed only)
   *  because smoothing made triangles near them cross (two sheets a voxel or two apart), or laid
   *  back onto the tiled surface where a finished piece crossed another. */
  std::size_t unsmoothedVertices = 0;
  /** Specks: pieces with less area than 48 equilateral triangles of the target edge (a few voxels),
   *  which the target edge would collapse. When a remesh is asked each is remeshed at its own
   *  scale (an edge that gives it about 48 triangles), smoothed and given its volume back;
   *  `smallPiecesRemeshed` counts those kept so, which also count as remeshed in piecesByFinish.
   *  `smallPiecesAsTiled` counts the others, left as tiled: the result was not a valid surface of
   *  the tiled topology, it crossed another piece, or only smoothing was asked (which leaves the
   *  tiling's slivers as they are). A speck left as tiled counts as finished as asked (no fallback). */
  std::size_t smallPiecesRemeshed = 0;
  std::size_t smallPiecesAsTiled = 0;
  /** Triangles of remeshed pieces kept as tiled: around the places where a piece's remesh crossed
   *  itself (two sheets closer than the target edge) or, once finished, crossed another piece (and
   *  still did with its vertices there laid back onto the tiling), the piece remeshed again around
   *  them. */
  std::size_t trianglesKeptTiled = 0;
  /** Edge flips and collapses and vertex moves (CrossingRepair) that undid the few places where a
   *  remesh crossed itself (a fold where two voxels touch along an edge, a chord through a gap a
   *  voxel wide) without remeshing the piece again, with those that then widened slivers there. */
  std::size_t crossingRepairOperations = 0;
  /** Edge flips and collapses that took away triangles with an angle under 30 degrees from valid
   *  finished pieces (NarrowTriangleWidening.h), where a structure is about as thin as an edge. */
  std::size_t narrowTrianglesWidened = 0;
  /** How many connected pieces got each finish, indexed by SurfaceFinish (specks left as tiled count
   *  under Tiled). All zero when the tiling was not split (an invalid tiling, or Tiled asked). */
  std::array<std::size_t, 3> piecesByFinish{};
};

/** The finishing the CLI applies to a mask of this voxel spacing (mm): edges of
 *  automaticEdgeLength(spacing), each piece's scaled by how it faces the grid (gridSpacing), and smoothing that moves no vertex farther than 0.3 of the voxel's
 *  side along each axis (the staircase is about that deep; a sharp edge is rounded no more). */
SurfaceFinishingOptions finishingOptionsFor(const std::array<double, 3>& spacing);

/** Finishes a tiling whose validation is given, one connected piece at a time: each piece is
 *  remeshed and smoothed and gets its tiled volume back, or, when a `targetVolume` (mm^3) is given
 *  (the voxels' volume: the tiling's chords sit slightly inside a curved surface), its target: a
 *  tiling of one piece targetVolume whatever its shortfall (a small structure in one slice is tiled
 *  well short of its slab); each of several pieces the `targetShares` that fall on it
 *  (pieceTargetVolumes), or without shares targetVolume shared in proportion to the tiled volumes,
 *  followed only within 25% of the piece's tiled volume (a voxel is tiled at a sixth of its
 *  volume, and an offset that large would bend a speck out of shape); where smoothing makes its triangles cross,
 *  the vertices around them (growing rings, three tries) go back to their remeshed positions. A piece
 *  is kept finished only if it is a valid surface of its tiled topology, facing the same way;
 *  otherwise it is smoothed only (put back to the tiling where sheets cross, likewise), else left
 *  as tiled. Remeshed pieces that cross each other once finished are remeshed again with their
 *  tiled triangles kept, unsmoothed, around the places where they cross (three rounds); pieces still
 *  crossing then go back to their tiled shape. Specks (smallPiecesRemeshed) are remeshed at an edge
 *  of their own size, else left as tiled; a finished speck that crosses another piece goes back to
 *  its tiled shape before any other piece is finished again. `fallback` says how many pieces got less than asked,
 *  and why the first did. `tilingValidation` may be without the self-intersection test (validateMeshTopology): then
 *  only what is kept as tiled is tested, and the finished pieces are tested in any case. A tiling
 *  that is not a closed, manifold, oriented surface (or that crosses itself, when tested) is
 *  returned as it is. The returned validation is always complete. Pieces are finished on up to
 *  `threads` threads (0: every core); the result does not depend on the number. */
FinishedSurface finishSurface(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                              const SurfaceFinishingOptions& options, unsigned int threads = 0,
                              double targetVolume = 0.0, const std::vector<ContourVolume>& targetShares = {});

/** "Remeshed", "Smoothed", "Tiled". */
const char* finishName(SurfaceFinish finish);

} // namespace slicemesh

#endif

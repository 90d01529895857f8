// Undoing a finished piece's few self-crossings where they are, by edge flips, collapses and vertex
// moves, so that a large piece is not remeshed whole again for a handful of folds.
#ifndef CrossingRepair_h
#define CrossingRepair_h

#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace slicemesh
{

/** What a local repair did to a mesh. */
struct CrossingRepair
{
  std::size_t flips = 0;
  std::size_t collapses = 0;
  std::size_t moves = 0; ///< vertices moved towards the mean of their neighbours
  std::size_t operations() const { return flips + collapses + moves; }
  /** Whether every crossing was undone, as judged against the triangles around them (the caller's
   *  validation of the whole mesh decides); when not, the mesh crosses itself still. */
  bool undone = false;
  /** When not undone: the pairs of triangles that still cross (lower number first), numbered as in
   *  the repaired mesh. */
  std::vector<std::pair<std::size_t, std::size_t>> stillCrossing;
  /** For every vertex of the repaired mesh, its number before (collapsed vertices are gone; a moved
   *  one's new point has the number of the vertex it moved). */
  std::vector<std::int32_t> formerVertex;
  /** For every vertex of the repaired mesh, whether it is a corner of a triangle the repair removed,
   *  rewrote or made (the corners, before and after, of each operation made, including those an
   *  undo took back). Elsewhere the triangles are as they were: the flags validateMeshAfterLocalChange
   *  asks for, since the repair moves no point in place (a moved vertex's triangles take a new one). */
  std::vector<char> changed;
};

/** Removes the crossings of `mesh` (`crossings`: pairs of triangle numbers, as the self-intersection
 *  test gives them) one at a time, greedily. Around the two triangles of a crossing it tries the
 *  flips and collapses of their edges and the edges at their corners, and moves of those edges'
 *  vertices to (and half way to) the mean of their neighbours; it makes the one that leaves fewer
 *  crossings nearby with the widest triangles. A crossing that none improves is passed over for
 *  the others until an operation changes the mesh. Only `movable` vertices (a flag per vertex)
 *  change: both ends of a flipped or collapsed edge, a moved vertex. A collapse moves no point (the
 *  surviving vertex stays where it is); a move gives the vertex's triangles a new point. An
 *  operation is made only if it keeps the surface a closed 2-manifold of the same topology (link
 *  condition; no edge twice), makes no degenerate triangle and none that faces against the
 *  triangles it replaces (their area normals summed), and reshapes nothing larger than a fold: no
 *  edge longer than twice `edgeLength` (mm, the remesh's target) is collapsed or made, no vertex
 *  moves farther, and the enclosed volume changes by at most edgeLength^3 / 8 per operation. The
 *  crossings are judged against the triangles around the movable vertices only: the caller
 *  validates the whole mesh after. Returns what it did; `mesh` is left without the removed
 *  triangles and vertices. */
CrossingRepair repairCrossingsLocally(TriangleMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& crossings,
                                      const std::vector<char>& movable, double edgeLength);

/** Each triangle of `movable` corners with an angle under `narrowAngleDegrees` (a remesh sliver
 *  beside a repaired fold; a finished piece's narrow triangles) flipped or collapsed away where that
 *  widens the narrowest angle among the triangles it changes and makes no crossing with the
 *  triangles around, under the bounds of repairCrossingsLocally; two sweeps. The caller validates
 *  the mesh after (the triangles that changed against the rest suffice). */
CrossingRepair widenNarrowTrianglesLocally(TriangleMesh& mesh, const std::vector<char>& movable, double edgeLength,
                                           double narrowAngleDegrees);

/** `perVertex` (arrays of one value per vertex; an empty one stays empty) renumbered as `repair`
 *  renumbered the vertices (CrossingRepair::formerVertex). */
template <typename... Arrays>
void renumber(const CrossingRepair& repair, Arrays&... perVertex)
{
  const auto one = [&](auto& values)
  {
    if (values.empty()) // held flags, without drawn contours
      return;
    std::remove_reference_t<decltype(values)> renumbered(repair.formerVertex.size());
    for (std::size_t v = 0; v < renumbered.size(); ++v)
      renumbered[v] = values[static_cast<std::size_t>(repair.formerVertex[v])];
    values.swap(renumbered);
  };
  (one(perVertex), ...);
}

} // namespace slicemesh

#endif

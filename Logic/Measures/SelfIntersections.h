// Where a triangle mesh crosses itself: the test every finished surface goes through before it is
// written, so it must be exact and cheap on a million triangles.
#ifndef SelfIntersections_h
#define SelfIntersections_h

#include "Core/SliceMeshTypes.h"

#include <utility>
#include <vector>

namespace slicemesh
{

/** The pairs of triangles (indices into mesh.triangles, first <= second, sorted) that intersect
 *  other than along what they share, by CGAL's rule for self-intersections: two triangles with a
 *  common edge intersect only if they fold onto each other (coplanar, on the same side of the
 *  edge); two with one common vertex if the edge opposite it in either meets the other; any other
 *  two if they touch at all. A degenerate triangle (collinear corners) is reported as (t, t) and not
 *  tested against the others. Exact (CGAL's filtered predicates); the same pairs as
 *  CGAL::Polygon_mesh_processing::self_intersections on any manifold mesh, and the same for any
 *  number of `threads` (0: every core).
 *
 *  Only triangles whose bounding boxes overlap are tested: their boxes are binned into a grid of
 *  cells about two triangles wide, each pair taken in the one cell that holds the lower corner of
 *  the boxes' overlap. Linear in the triangles for a mesh of triangles of similar size; no
 *  half-edge structure is built. */
std::vector<std::pair<std::size_t, std::size_t>> selfIntersectingTrianglePairs(const TriangleMesh& mesh,
                                                                               unsigned int threads = 0);

/** selfIntersectingTrianglePairs with the grid's boxes filed into its cells a group of cells at a
 *  time, each group of at most about `entriesPerGroup` filings (a box is filed in each cell it
 *  covers; a group holds at least one run of cells, however many filings that is). Fewer at a time
 *  hold less memory and walk the boxes once more per group; the same pairs for any value. 0: as
 *  many as there are boxes, and at least about a million (what selfIntersectingTrianglePairs does). */
std::vector<std::pair<std::size_t, std::size_t>>
selfIntersectingTrianglePairsInGroups(const TriangleMesh& mesh, std::size_t entriesPerGroup, unsigned int threads = 0);

/** Whether triangles s and t, corners numbered into `points`, intersect by the rule of
 *  selfIntersectingTrianglePairs (exact). For a repair that tries triangles before making them. */
bool trianglesCross(const std::vector<Point3>& points, const Triangle& s, const Triangle& t);

/** selfIntersectingTrianglePairs of `mesh` after some of its vertices moved (`moved`, a flag per
 *  vertex), from `before`, the pairs of the same triangles before the move: a pair of which neither
 *  triangle has a moved corner is as it was, so only the pairs with a triangle that moved are
 *  tested (against every triangle whose box meets its box). The same pairs as the whole test, at
 *  the cost of the few triangles that moved: a finished piece is put back where it crossed itself a
 *  few times, and the whole test of a piece of half a million triangles took half a second each time. */
std::vector<std::pair<std::size_t, std::size_t>>
selfIntersectingTrianglePairsAfterMoving(const TriangleMesh& mesh,
                                         const std::vector<std::pair<std::size_t, std::size_t>>& before,
                                         const std::vector<char>& moved, unsigned int threads = 0);

} // namespace slicemesh

#endif

// The edges of a tiling (or of a surface finished from it) that run along drawn contours: what the
// finishing of a structure set's surface keeps, so that the surface passes through the contours.
#ifndef HeldContourEdges_h
#define HeldContourEdges_h

#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace slicemesh
{

struct HeldContourEdges
{
  /** One flag per vertex of the mesh: it lies on a contour of its slice. */
  std::vector<char> vertices;
  /** The edges (lower vertex index first) whose two ends and middle lie on a contour of their slice:
   *  the contour's own edges, or pieces of them where the tiling put a crossing point on one. */
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  /** One flag per vertex: it lies on two of `edges` whose other ends lie on one straight line with
   *  it (a crossing point the tiling put on a contour edge, a point on a straight stretch): merged
   *  into a neighbour along them, it leaves the contour as it was. */
  std::vector<char> straight;

  bool empty() const { return edges.empty(); }
};

/** How far (mm) from a contour a point of its slice plane counts as on it: the tiling puts contour
 *  points and the crossings on contour edges at the contours' own coordinates, up to rounding. */
constexpr double onContourTolerance = 1e-6;

/** The vertices and edges of `mesh` (in the frame of `contours`: the stack it was tiled from) that
 *  lie on the contours: a vertex within onContourTolerance of a slice's plane and of one of its
 *  contours, an edge whose two ends lie in one slice and whose middle lies on a contour there. A
 *  chord between two contour points (across a cap laid flat on its slice) is no contour edge. */
HeldContourEdges heldContourEdges(const TriangleMesh& mesh, const ContourStack& contours);

} // namespace slicemesh

#endif

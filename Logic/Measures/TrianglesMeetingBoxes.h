// Which triangles of a mesh meet each of a set of boxes: the step before the exact tests of
// crossings, between pieces and after some vertices of a piece moved.
#ifndef TrianglesMeetingBoxes_h
#define TrianglesMeetingBoxes_h

#include "Core/BoundingBox.h"
#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <vector>

namespace slicemesh
{

/** For box b, the triangles whose boxes share a point with it (touching counts) are
 *  triangles[start[b]] to triangles[start[b + 1]], in increasing order. */
struct TrianglesMeeting
{
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> triangles;
};

/** The triangles of `mesh` that meet each of `boxes`. The boxes are filed under the cells of space
 *  they cover (cells as wide as all but the widest tenth of the boxes, and at least two triangles);
 *  one pass over the triangles, in ranges on up to `threads` threads (0: every core), looks up the
 *  cells each triangle's box covers; boxes over many cells are tried by every triangle. Linear in
 *  the triangles where a CGAL box intersection sorts them all on one thread. The same answer on any
 *  number of threads. */
TrianglesMeeting trianglesMeetingBoxes(const TriangleMesh& mesh, const std::vector<BoundingBox>& boxes,
                                       unsigned int threads = 1);

} // namespace slicemesh

#endif

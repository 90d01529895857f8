// Which of many boxes meet: the first step of the nesting and crossing tests of contours and of
// surfaces, where most of the items meet none of the others.
#ifndef MeetingBoxes_h
#define MeetingBoxes_h

#include "Core/BoundingBox.h"
#include "Core/PlanarGeometry.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace slicemesh
{

/** The pairs (i, j), i < j, of boxes that share a point (touching counts), in increasing order, from
 *  CGAL's box intersection: n log n in the boxes plus the pairs, not every pair. An empty box (low
 *  above high: a mesh without triangles) meets none. */
std::vector<std::pair<std::size_t, std::size_t>> meetingBoxes(const std::vector<BoundingBox>& boxes);
std::vector<std::pair<std::size_t, std::size_t>> meetingBoxes(const std::vector<Box2>& boxes);

} // namespace slicemesh

#endif

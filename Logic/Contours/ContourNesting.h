// Stage: clean, orient and nest the contours of one slice.
#ifndef ContourNesting_h
#define ContourNesting_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Nesting of the contours of one slice: parent[i] is the innermost contour containing contour i
 *  (-1 for none) and depth[i] the number of contours containing it. Even depth: an outer boundary;
 *  odd depth: a hole. */
struct ContourNesting
{
  std::vector<int> parent;
  std::vector<int> depth;

  bool isHole(std::size_t i) const { return depth[i] % 2 == 1; }
};

/** Removes consecutive points closer than tolerance (mm) and spikes that turn straight back;
 *  returns an empty polygon when fewer than three points remain, or (dropArealess) no area. */
Polygon2 cleanContour(const Polygon2& contour, double tolerance, bool dropArealess = true);

/** Orients the contours in place, outer boundaries counter-clockwise and holes clockwise (seen from +z),
 *  so the solid is always on the left of a contour, and returns their nesting. */
ContourNesting orientAndNest(std::vector<Polygon2>& contours);

} // namespace slicemesh

#endif

// Simplification of closed contours within a distance tolerance, without creating crossings.
#ifndef ContourSimplification_h
#define ContourSimplification_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Simplifies every contour of one slice: keeps a subset of its points such that every dropped
 *  point lies within `tolerance` (mm) of the edge that replaces it (Douglas-Peucker on the closed
 *  contour, anchored at its first point and the point farthest from it). Then, as long as two kept
 *  edges of the slice cross or touch (of one contour or of two), the dropped point farthest from
 *  each such edge is put back (Saalfeld's topology-preserving repair): the result has no crossing
 *  that the input did not have, and nesting is unchanged. Every contour stays a proper polygon:
 *  while it has fewer than 3 points or less than half its traced area, the dropped point farthest
 *  from its kept edge is put back (a contour thinner than the tolerance keeps its width).
 *  With maxEdgeLength > 0, a kept edge longer than that (mm) keeps the dropped point half way along
 *  it, by count, until none is or no point is left between: a straight run of a thousand pixels
 *  stays a few hundred edges, not one, which would give the tiling needles as long as the run.
 *  tolerance <= 0 returns the contours unchanged. */
std::vector<Polygon2> simplifyContours(const std::vector<Polygon2>& contours, double tolerance,
                                       double maxEdgeLength = 0.0);

/** simplifyContours on every slice of the stack. */
ContourStack simplifyContours(const ContourStack& stack, double tolerance, double maxEdgeLength = 0.0);

} // namespace slicemesh

#endif

// Resampling of closed contours to a target point spacing along their length.
#ifndef ContourResampling_h
#define ContourResampling_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** The fewest points resampleContour leaves a contour that had at least as many. */
constexpr std::size_t fewestResampledPoints = 8;

/** Points at equal arc-length steps along the closed contour, starting at its first point, with
 *  n = max(round(length / spacing), min(its own points, fewestResampledPoints), 3) points (so the
 *  step is as close to `spacing` mm as a whole number of steps allows, and a small contour keeps
 *  its shape). spacing <= 0 or a contour of zero length returns it unchanged. */
Polygon2 resampleContour(const Polygon2& contour, double spacing);

/** resampleContour, then the resampled contour grown along its normals until it encloses the
 *  area of the input (ContourSmoothing.h, offsetToArea): chords cut convex corners and bulges, and
 *  on a small structure with corners (a box a few voxels wide) that loses several percent of its
 *  volume. The points then lie off the input polyline by about a third of the chords' sagitta. */
Polygon2 resampleContourKeepingArea(const Polygon2& contour, double spacing);

/** resampleContour on every contour of one slice, without creating crossings: a resampled contour
 *  that would cross or touch itself or another contour of the slice (a chord cutting across a thin
 *  neck or a narrow gap) is resampled again at half the spacing, up to four times, and otherwise
 *  kept as it was. keepArea: resampleContourKeepingArea instead. */
std::vector<Polygon2> resampleContours(const std::vector<Polygon2>& contours, double spacing, bool keepArea = false);

/** resampleContours on every slice of the stack; keepArea uses resampleContourKeepingArea. */
ContourStack resampleContours(const ContourStack& stack, double spacing, bool keepArea = false);

/** Mean length of the contour edges of the stack (mm): its in-plane point spacing; 0 when empty. */
double meanPointSpacing(const ContourStack& stack);

} // namespace slicemesh

#endif

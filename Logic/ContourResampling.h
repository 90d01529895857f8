// Resampling of closed contours to a target point spacing along their length.
#ifndef ContourResampling_h
#define ContourResampling_h

#include "SliceMeshTypes.h"

namespace slicemesh
{

/** Points at equal arc-length steps along the closed contour, starting at its first point, with
 *  n = max(3, round(length / spacing)) points (so the step is as close to `spacing` mm as a whole
 *  number of steps allows). spacing <= 0 or a contour of zero length returns it unchanged. */
Polygon2 resampleContour(const Polygon2& contour, double spacing);

/** resampleContour on every contour of one slice, without creating crossings: a resampled contour
 *  that would cross or touch itself or another contour of the slice (a chord cutting across a thin
 *  neck or a narrow gap) is resampled again at half the spacing, up to four times, and otherwise
 *  kept as it was. */
std::vector<Polygon2> resampleContours(const std::vector<Polygon2>& contours, double spacing);

/** resampleContours on every slice of the stack. */
ContourStack resampleContours(const ContourStack& stack, double spacing);

/** Mean length of the contour edges of the stack (mm): its in-plane point spacing; 0 when empty. */
double meanPointSpacing(const ContourStack& stack);

} // namespace slicemesh

#endif

// Resampling of closed contours to a target point spacing along their length.
#ifndef ContourResampling_h
#define ContourResampling_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** The fewest points resampleContour leaves a contour that had at least as many. */
constexpr std::size_t fewestResampledPoints = 8;

/** The fewest points resampleContourKeepingCorners leaves a drawn contour that had at least as many. */
constexpr std::size_t fewestDrawnPoints = 16;

/** A drawn contour's corner turns by more than this (degrees): a square's turn 90, a circle drawn
 *  with 32 points 11.25. */
constexpr double cornerTurnDegrees = 30.0;

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

/** A drawn contour's corners: the indices (increasing) of the points where it turns by more than
 *  `turnDegrees`. Of corners closer along the contour than `spacing` / 2, only the sharpest is a
 *  corner: a jagged run of points would otherwise pin the resampled contour to edges far shorter
 *  than the spacing. */
std::vector<std::size_t> contourCorners(const Polygon2& contour, double spacing, double turnDegrees = cornerTurnDegrees);

/** Points at even arc-length steps along the contour between its corners (contourCorners), each
 *  corner kept exactly: every stretch from one corner to the next gets max(1, round(length /
 *  spacing)) steps, the spacing at most a fewestDrawnPoints-th of the perimeter. Every point lies on the input polyline, so a drawn square stays a square and a
 *  slot narrower than the spacing keeps its walls. A contour without corners is resampleContour. */
Polygon2 resampleContourKeepingCorners(const Polygon2& contour, double spacing);

/** How resampleContours places the points. */
enum class ResampledShape
{
  Chords,        ///< resampleContour: evenly along the polyline, from its first point
  KeepingArea,   ///< resampleContourKeepingArea: traced contours, whose corners are a staircase's
  KeepingCorners ///< resampleContourKeepingCorners: drawn contours, whose points are the anatomy
};

/** resampleContour (or `shape`'s resampling) on every contour of one slice, without creating
 *  crossings: a resampled contour that would cross or touch itself or another contour of the slice
 *  (a chord cutting across a thin neck or a narrow gap) is resampled again at half the spacing, up
 *  to four times, and otherwise kept as it was. */
std::vector<Polygon2> resampleContours(const std::vector<Polygon2>& contours, double spacing,
                                       ResampledShape shape = ResampledShape::Chords);

/** resampleContours on every slice of the stack. */
ContourStack resampleContours(const ContourStack& stack, double spacing, ResampledShape shape = ResampledShape::Chords);

/** Mean length of the contour edges of the stack (mm): its in-plane point spacing; 0 when empty. */
double meanPointSpacing(const ContourStack& stack);

} // namespace slicemesh

#endif

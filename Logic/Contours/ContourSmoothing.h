// Non-shrinking smoothing of closed contours (Taubin's lambda/mu filter), bounded and crossing-free.
#ifndef ContourSmoothing_h
#define ContourSmoothing_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

struct ContourSmoothingOptions
{
  /** Number of lambda/mu step pairs; 0 turns smoothing off. */
  int iterations = 0;
  /** Taubin's shrinking and inflating factors: the pass band is k = 1/lambda + 1/mu (about 0.11
   *  here), so a contour's low frequencies (its shape) pass and the voxel staircase (periods of a
   *  few points) is damped. */
  double lambda = 0.5;
  double mu = -0.53;
  /** No point moves farther than this from where it was traced (mm). The safety of the result
   *  rests on it: contours that were apart by more than twice this cannot meet. 0: unbounded. */
  double maxDisplacement = 0.0;
};

/** Moves every point of the closed contour along its normal (the normal of the chord between its
 *  neighbours, to the right of the direction of travel) by one common distance, found by a few
 *  Newton steps, so that its signed area becomes `area` (to 1e-9 relative, unless the clamp stops
 *  it): the same shape, grown or shrunk. With `anchor` (a polygon of the same size), no point ends
 *  farther than maxDisplacement from its anchor point. Contours of fewer than 3 points are left. */
void offsetToArea(Polygon2& contour, double area, const Polygon2* anchor = nullptr, double maxDisplacement = 0.0);

/** Smooths one closed contour: `iterations` pairs of a lambda step and a mu step of the umbrella
 *  operator p_i += f * ((p_{i-1} + p_{i+1}) / 2 - p_i), after each pair every point clamped back to
 *  within maxDisplacement of its original position. Taubin's filter does not shrink long contours,
 *  but it does shrink contours of a few points (their whole shape is above the pass band), so the
 *  enclosed area is then restored by moving every point along its normal by the same distance
 *  (within the same clamp). Contours of fewer than 4 points come back unchanged.
 *  G. Taubin, "A signal processing approach to fair surface design", SIGGRAPH 1995. */
Polygon2 smoothContour(const Polygon2& contour, const ContourSmoothingOptions& options);

/** smoothContour on every contour of one slice, never creating a crossing: while smoothed contours
 *  cross or touch themselves or each other (ContourCrossings.h), the offending ones go back to their
 *  traced shape. Input contours that already cross keep whatever they had. */
std::vector<Polygon2> smoothContours(const std::vector<Polygon2>& contours, const ContourSmoothingOptions& options);

/** smoothContours on every slice of the stack. */
ContourStack smoothContours(const ContourStack& stack, const ContourSmoothingOptions& options);

} // namespace slicemesh

#endif

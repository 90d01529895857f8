// The smoothing's displacement bound: a displacement that has left an axis-aligned ellipsoid taken
// back to the ellipsoid's nearest point. Internal to the finishing (SurfaceSmoothing and its packed
// steps, in double and in single precision).
#ifndef EllipsoidClamp_h
#define EllipsoidClamp_h

#include <array>
#include <cmath>
#include <limits>

namespace slicemesh
{

/** The factors f (one per axis) that take a displacement d to f * d, the point of the ellipsoid
 *  nearest to d, for a d outside it. `u` is d in units of the semi-axes (d_i / a_i, squared sum over
 *  1) and `w` the squared reciprocal semi-axes (1 / a_i^2).
 *
 *  Why the nearest point and not d scaled down onto the ellipsoid: on a grid whose slices are thinner
 *  than its pixels the ellipsoid is flat, and a vertex on a wall across the slices that drifts along
 *  the wall by a fraction of a slice while it smooths out the pixels' staircase would have its whole
 *  move, across the wall too, shortened by that drift. The nearest point keeps the move across the
 *  wall and cuts the drift. On a sphere (equal axes) the two are the same point.
 *
 *  The nearest point is x_i = d_i / (1 + t w_i), with t > 0 the root of
 *  g(t) = sum_i (u_i / (1 + t w_i))^2 - 1, which falls and is convex: Newton's steps from t = 0 stay
 *  below the root and approach it from outside the ellipsoid, so the last point is scaled onto it. */
template <typename Real>
std::array<Real, 3> nearestOnEllipsoidFactors(const std::array<Real, 3>& u, const std::array<Real, 3>& w)
{
  if (w[0] == w[1] && w[1] == w[2]) // a sphere: the nearest point is on the ray, found without steps
  {
    const Real onto = Real(1) / std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    return { onto, onto, onto };
  }
  // Steps stop once the point is within a few roundings of the ellipsoid (the scaling below puts it
  // on); from a move one or two bounds long, three or four steps get there.
  constexpr int newtonSteps = 6;
  const Real closeEnough = Real(16) * std::numeric_limits<Real>::epsilon();
  Real t = 0;
  std::array<Real, 3> f{ 1, 1, 1 };
  for (int step = 0; step < newtonSteps; ++step)
  {
    Real g = -1, slope = 0;
    for (int i = 0; i < 3; ++i)
    {
      f[i] = Real(1) / (Real(1) + t * w[i]);
      const Real reach = u[i] * f[i];
      g += reach * reach;
      slope -= Real(2) * reach * reach * w[i] * f[i];
    }
    if (!(g > closeEnough) || !(slope < Real(0)))
      break;
    t -= g / slope;
  }
  Real reachSquared = 0;
  for (int i = 0; i < 3; ++i)
  {
    f[i] = Real(1) / (Real(1) + t * w[i]);
    reachSquared += (u[i] * f[i]) * (u[i] * f[i]);
  }
  if (reachSquared > Real(1))
  {
    const Real onto = Real(1) / std::sqrt(reachSquared);
    for (Real& factor : f)
      factor *= onto;
  }
  return f;
}

} // namespace slicemesh

#endif

// A tube of radius r around a helix with round ends: the points within r of the curve
// c(t) = center + R cos(t) e1 + R sin(t) e2 + (pitch t / 2 pi) axis, t in [0, 2 pi turns].
// Signed distance: distance to the curve minus r, exact (the distance to the curve is minimised
// numerically: every local minimum of a fine sampling of t is refined by golden-section search to
// 1e-10 in t) provided r is below the curve's radius of curvature (R^2 + c^2) / R, c = pitch / 2 pi,
// and the turns stay apart (pitch > 2 r); the constructor checks both.
// Volume: pi r^2 L + 4/3 pi r^3 (L the curve's length; Pappus for the tube, a half ball at each end).
#ifndef HelixTube_h
#define HelixTube_h

#include "Phantom.h"

namespace slicemesh
{

class HelixTube : public Phantom
{
public:
  /** Axis of the helix along +z; radius R of the helix, pitch (rise per turn), turns, tube radius r. */
  HelixTube(const Vector3& center, double helixRadius, double pitch, double turns, double tubeRadius);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

  /** The distance from point to the helix curve. */
  double distanceToCurve(const Vector3& point) const;

private:
  Vector3 curve(double t) const;

  Vector3 m_Center;
  double m_HelixRadius;
  double m_Rise; ///< pitch / 2 pi
  double m_End;  ///< 2 pi turns
  double m_TubeRadius;
};

} // namespace slicemesh

#endif

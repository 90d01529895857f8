// An ellipsoid, possibly rotated. Its distance function has no closed form: it is the root of a
// one-dimensional equation (Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a
// Hyperellipsoid", Geometric Tools, 2013), solved here by safeguarded Newton iteration.
#ifndef Ellipsoid_h
#define Ellipsoid_h

#include "Phantom.h"

namespace slicemesh
{

class Ellipsoid : public Phantom
{
public:
  /** radii along the shape's own axes, which are the columns of rotation. */
  Ellipsoid(const Vector3& center, const Vector3& radii, const Matrix3& rotation = Matrix3::Identity());
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  Vector3 m_Center;
  Vector3 m_Radii;
  Matrix3 m_Rotation;
};

} // namespace slicemesh

#endif

// A solid cylinder with flat ends: center, axis direction, radius, half of its length.
#ifndef CappedCylinder_h
#define CappedCylinder_h

#include "Phantom.h"

namespace slicemesh
{

class CappedCylinder : public Phantom
{
public:
  CappedCylinder(const Vector3& center, const Vector3& axis, double radius, double halfLength);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  Vector3 m_Center;
  Vector3 m_Axis;
  double  m_Radius;
  double  m_HalfLength;
};

} // namespace slicemesh

#endif

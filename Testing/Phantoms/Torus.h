// A ring torus: center, axis of revolution, major radius R (centre to tube centre), minor radius r < R.
#ifndef Torus_h
#define Torus_h

#include "Phantom.h"

namespace slicemesh
{

class Torus : public Phantom
{
public:
  Torus(const Vector3& center, const Vector3& axis, double majorRadius, double minorRadius);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  Vector3 m_Center;
  Vector3 m_Axis;
  double  m_MajorRadius;
  double  m_MinorRadius;
};

} // namespace slicemesh

#endif

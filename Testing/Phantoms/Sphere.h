// A ball: the simplest phantom, with a closed-form signed distance.
#ifndef Sphere_h
#define Sphere_h

#include "Phantom.h"

namespace slicemesh
{

class Sphere : public Phantom
{
public:
  Sphere(const Vector3& center, double radius);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  Vector3 m_Center;
  double  m_Radius;
};

} // namespace slicemesh

#endif

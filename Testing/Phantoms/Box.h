// A rectangular box, possibly rotated: center, half sizes along its own axes (the columns of rotation).
#ifndef Box_h
#define Box_h

#include "Phantom.h"

namespace slicemesh
{

class Box : public Phantom
{
public:
  Box(const Vector3& center, const Vector3& halfSizes, const Matrix3& rotation = Matrix3::Identity());
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  Vector3 m_Center;
  Vector3 m_HalfSizes;
  Matrix3 m_Rotation;
};

} // namespace slicemesh

#endif

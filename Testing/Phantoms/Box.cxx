#include "Box.h"

#include <cmath>
#include <stdexcept>

namespace slicemesh
{

Box::Box(const Vector3& center, const Vector3& halfSizes, const Matrix3& rotation)
  : m_Center(center)
  , m_HalfSizes(halfSizes)
  , m_Rotation(rotation)
{
  if (!halfSizes.allFinite() || !(halfSizes.minCoeff() > 0.0))
    throw std::invalid_argument("Box: the half sizes must be positive");
  checkRotation(rotation);
}

double Box::signedDistance(const Vector3& point) const
{
  // Distance to the box in its own frame: outside, the length of the excess over the half sizes;
  // inside, minus the distance to the nearest face.
  const Vector3 excess = (m_Rotation.transpose() * (point - m_Center)).cwiseAbs() - m_HalfSizes;
  const double outside = excess.cwiseMax(0.0).norm();
  const double inside = std::min(excess.maxCoeff(), 0.0);
  return outside + inside;
}

double Box::volume() const
{
  return 8.0 * m_HalfSizes.prod();
}

Bounds Box::bounds() const
{
  const Vector3 halfExtent = m_Rotation.cwiseAbs() * m_HalfSizes;
  return { m_Center - halfExtent, m_Center + halfExtent };
}

} // namespace slicemesh

#include "CappedCylinder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slicemesh
{

CappedCylinder::CappedCylinder(const Vector3& center, const Vector3& axis, double radius, double halfLength)
  : m_Center(center)
  , m_Axis(unitAxis(axis))
  , m_Radius(radius)
  , m_HalfLength(halfLength)
{
  if (!(radius > 0.0) || !(halfLength > 0.0) || !std::isfinite(radius) || !std::isfinite(halfLength))
    throw std::invalid_argument("CappedCylinder: the radius and half length must be positive");
}

double CappedCylinder::signedDistance(const Vector3& point) const
{
  // In the (radial, axial) half plane the solid is a rectangle; this is the rectangle's distance.
  const Vector3 offset = point - m_Center;
  const double axial = offset.dot(m_Axis);
  const double radial = (offset - axial * m_Axis).norm();
  const double dr = radial - m_Radius;
  const double da = std::abs(axial) - m_HalfLength;
  const double outside = std::hypot(std::max(dr, 0.0), std::max(da, 0.0));
  const double inside = std::min(std::max(dr, da), 0.0);
  return outside + inside;
}

double CappedCylinder::volume() const
{
  return M_PI * m_Radius * m_Radius * 2.0 * m_HalfLength;
}

Bounds CappedCylinder::bounds() const
{
  // Along a coordinate axis k: the axis segment reaches halfLength * |a_k|, each end disc
  // radius * sqrt(1 - a_k^2).
  Vector3 halfExtent;
  for (int k = 0; k < 3; ++k)
    halfExtent[k] = m_HalfLength * std::abs(m_Axis[k]) + m_Radius * std::sqrt(std::max(0.0, 1.0 - m_Axis[k] * m_Axis[k]));
  return { m_Center - halfExtent, m_Center + halfExtent };
}

} // namespace slicemesh

#include "Torus.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slicemesh
{

Torus::Torus(const Vector3& center, const Vector3& axis, double majorRadius, double minorRadius)
  : m_Center(center)
  , m_Axis(unitAxis(axis))
  , m_MajorRadius(majorRadius)
  , m_MinorRadius(minorRadius)
{
  if (!(minorRadius > 0.0) || !(majorRadius > minorRadius) || !std::isfinite(majorRadius))
    throw std::invalid_argument("Torus: needs 0 < minor radius < major radius (a ring torus)");
}

double Torus::signedDistance(const Vector3& point) const
{
  // Distance to the tube's centre circle, minus the tube radius.
  const Vector3 offset = point - m_Center;
  const double axial = offset.dot(m_Axis);
  const double radial = (offset - axial * m_Axis).norm();
  return std::hypot(radial - m_MajorRadius, axial) - m_MinorRadius;
}

double Torus::volume() const
{
  return 2.0 * M_PI * M_PI * m_MajorRadius * m_MinorRadius * m_MinorRadius;
}

Bounds Torus::bounds() const
{
  // The centre circle reaches R * sqrt(1 - a_k^2) along coordinate axis k; the tube adds r.
  Vector3 halfExtent;
  for (int k = 0; k < 3; ++k)
    halfExtent[k] = m_MajorRadius * std::sqrt(std::max(0.0, 1.0 - m_Axis[k] * m_Axis[k])) + m_MinorRadius;
  return { m_Center - halfExtent, m_Center + halfExtent };
}

} // namespace slicemesh

#include "Sphere.h"

#include <cmath>
#include <stdexcept>

namespace slicemesh
{

Sphere::Sphere(const Vector3& center, double radius)
  : m_Center(center)
  , m_Radius(radius)
{
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("Sphere: the radius must be positive");
}

double Sphere::signedDistance(const Vector3& point) const
{
  return (point - m_Center).norm() - m_Radius;
}

double Sphere::volume() const
{
  return 4.0 / 3.0 * M_PI * m_Radius * m_Radius * m_Radius;
}

Bounds Sphere::bounds() const
{
  return { m_Center.array() - m_Radius, m_Center.array() + m_Radius };
}

} // namespace slicemesh

#include "HelixTube.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace slicemesh
{

HelixTube::HelixTube(const Vector3& center, double helixRadius, double pitch, double turns, double tubeRadius)
  : m_Center(center)
  , m_HelixRadius(helixRadius)
  , m_Rise(pitch / (2.0 * M_PI))
  , m_End(2.0 * M_PI * turns)
  , m_TubeRadius(tubeRadius)
{
  if (!(helixRadius > 0.0) || !(pitch > 0.0) || !(turns > 0.0) || !(tubeRadius > 0.0))
    throw std::invalid_argument("HelixTube: radii, pitch and turns must be positive");
  const double curvatureRadius = (helixRadius * helixRadius + m_Rise * m_Rise) / helixRadius;
  if (!(tubeRadius < curvatureRadius) || !(pitch > 2.0 * tubeRadius))
    throw std::invalid_argument("HelixTube: the tube must be thinner than the curvature radius and the turns apart");
}

Vector3 HelixTube::curve(double t) const
{
  return m_Center + Vector3(m_HelixRadius * std::cos(t), m_HelixRadius * std::sin(t), m_Rise * t);
}

double HelixTube::distanceToCurve(const Vector3& point) const
{
  // |p - c(t)|^2 has at most one local minimum per interval shorter than the curvature allows;
  // 96 samples per turn, then golden-section search around every sampled local minimum.
  const int samples = std::max(8, static_cast<int>(std::ceil(96.0 * m_End / (2.0 * M_PI))));
  const double step = m_End / samples;
  std::vector<double> d2(samples + 1);
  for (int i = 0; i <= samples; ++i)
    d2[i] = (point - curve(i * step)).squaredNorm();
  auto f = [&](double t) { return (point - curve(t)).squaredNorm(); };
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= samples; ++i)
  {
    const bool localMinimum = (i == 0 || d2[i] <= d2[i - 1]) && (i == samples || d2[i] <= d2[i + 1]);
    if (!localMinimum)
      continue;
    double a = std::max(0.0, (i - 1) * step), b = std::min(m_End, (i + 1) * step);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    while (b - a > 1e-10)
    {
      if (fc < fd)
      {
        b = d;
        d = c;
        fd = fc;
        c = b - g * (b - a);
        fc = f(c);
      }
      else
      {
        a = c;
        c = d;
        fc = fd;
        d = a + g * (b - a);
        fd = f(d);
      }
    }
    best = std::min({ best, d2[i], f(0.5 * (a + b)) });
  }
  return std::sqrt(best);
}

double HelixTube::signedDistance(const Vector3& point) const
{
  return distanceToCurve(point) - m_TubeRadius;
}

double HelixTube::volume() const
{
  const double length = m_End * std::hypot(m_HelixRadius, m_Rise);
  const double r = m_TubeRadius;
  return M_PI * r * r * length + 4.0 / 3.0 * M_PI * r * r * r;
}

Bounds HelixTube::bounds() const
{
  // A box around the helix's cylinder: tight in z, and in x, y once the helix makes a full turn.
  const double reach = m_HelixRadius + m_TubeRadius;
  return { m_Center + Vector3(-reach, -reach, -m_TubeRadius),
           m_Center + Vector3(reach, reach, m_Rise * m_End + m_TubeRadius) };
}

} // namespace slicemesh

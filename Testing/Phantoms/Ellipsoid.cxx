#include "Ellipsoid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace slicemesh
{
namespace
{

/** The root u > 0 of F(u) = sum_i (a_i / (u + b_i))^2 - 1 with a_i > 0, b_i >= 0, bracketed by
 *  lower <= u <= upper. F decreases and is convex, so Newton's steps from the lower end of the
 *  bracket climb monotonically to the root; the bracket only guards against rounding. */
template <std::size_t N>
double secularRoot(const std::array<double, N>& a, const std::array<double, N>& b, double lower, double upper)
{
  double u = lower;
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    double f = -1.0;
    double slope = 0.0;
    for (std::size_t i = 0; i < N; ++i)
    {
      const double ratio = a[i] / (u + b[i]);
      f += ratio * ratio;
      slope -= 2.0 * ratio * ratio / (u + b[i]);
    }
    if (f == 0.0)
      return u;
    if (f > 0.0)
      lower = u;
    else
      upper = u;
    double next = u - f / slope;
    if (!(next > lower && next < upper))
      next = 0.5 * (lower + upper);
    if (std::abs(next - u) <= 4.0 * std::numeric_limits<double>::epsilon() * u)
      return next;
    u = next;
  }
  return u;
}

/** Distance from (y0, y1), both >= 0, to the ellipse with semi-axes e0 >= e1 > 0. */
double distanceToEllipse(double e0, double e1, double y0, double y1)
{
  if (y1 > 0.0)
  {
    if (y0 > 0.0)
    {
      // u = t + e1^2 where t is the Lagrange parameter of the closest point.
      const std::array<double, 2> a{ e0 * y0, e1 * y1 };
      const std::array<double, 2> b{ e0 * e0 - e1 * e1, 0.0 };
      const double u = secularRoot(a, b, e1 * y1, std::hypot(a[0], a[1]));
      const double x0 = e0 * e0 * y0 / (u + b[0]);
      const double x1 = e1 * e1 * y1 / u;
      return std::hypot(x0 - y0, x1 - y1);
    }
    return std::abs(y1 - e1);
  }
  // On the major axis: inside the evolute the closest point is off the axis.
  const double denominator = e0 * e0 - e1 * e1;
  if (e0 * y0 < denominator)
  {
    const double x0 = e0 * e0 * y0 / denominator;
    const double x1 = e1 * std::sqrt(std::max(0.0, 1.0 - (x0 / e0) * (x0 / e0)));
    return std::hypot(x0 - y0, x1);
  }
  return std::abs(y0 - e0);
}

/** Distance from y (all >= 0) to the ellipsoid with semi-axes e0 >= e1 >= e2 > 0. */
double distanceToEllipsoid(const std::array<double, 3>& e, const std::array<double, 3>& y)
{
  if (y[2] > 0.0)
  {
    if (y[1] > 0.0)
    {
      if (y[0] > 0.0)
      {
        const double e2sq = e[2] * e[2];
        const std::array<double, 3> a{ e[0] * y[0], e[1] * y[1], e[2] * y[2] };
        const std::array<double, 3> b{ e[0] * e[0] - e2sq, e[1] * e[1] - e2sq, 0.0 };
        const double u = secularRoot(a, b, e[2] * y[2], std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
        double squared = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          const double x = e[i] * e[i] * y[i] / (u + b[i]);
          squared += (x - y[i]) * (x - y[i]);
        }
        return std::sqrt(squared);
      }
      return distanceToEllipse(e[1], e[2], y[1], y[2]);
    }
    if (y[0] > 0.0)
      return distanceToEllipse(e[0], e[2], y[0], y[2]);
    return std::abs(y[2] - e[2]);
  }
  // In the plane of the two larger axes: inside the evolute the closest point leaves the plane.
  const double denominator0 = e[0] * e[0] - e[2] * e[2];
  const double denominator1 = e[1] * e[1] - e[2] * e[2];
  const double n0 = e[0] * y[0];
  const double n1 = e[1] * y[1];
  if (n0 < denominator0 && n1 < denominator1)
  {
    const double r0 = n0 / denominator0;
    const double r1 = n1 / denominator1;
    const double discriminant = 1.0 - r0 * r0 - r1 * r1;
    if (discriminant > 0.0)
    {
      const double x0 = e[0] * r0;
      const double x1 = e[1] * r1;
      const double x2 = e[2] * std::sqrt(discriminant);
      return std::sqrt((x0 - y[0]) * (x0 - y[0]) + (x1 - y[1]) * (x1 - y[1]) + x2 * x2);
    }
  }
  return distanceToEllipse(e[0], e[1], y[0], y[1]);
}

} // namespace

Ellipsoid::Ellipsoid(const Vector3& center, const Vector3& radii, const Matrix3& rotation)
  : m_Center(center)
  , m_Radii(radii)
  , m_Rotation(rotation)
{
  if (!radii.allFinite() || !(radii.minCoeff() > 0.0))
    throw std::invalid_argument("Ellipsoid: the radii must be positive");
  checkRotation(rotation);
}

double Ellipsoid::signedDistance(const Vector3& point) const
{
  const Vector3 local = m_Rotation.transpose() * (point - m_Center);
  // By symmetry work in the first octant, with the axes sorted from longest to shortest.
  std::array<int, 3> order{ 0, 1, 2 };
  std::sort(order.begin(), order.end(), [this](int p, int q) { return m_Radii[p] > m_Radii[q]; });
  std::array<double, 3> e;
  std::array<double, 3> y;
  double level = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    e[i] = m_Radii[order[i]];
    y[i] = std::abs(local[order[i]]);
    level += (y[i] / e[i]) * (y[i] / e[i]);
  }
  const double distance = distanceToEllipsoid(e, y);
  return level < 1.0 ? -distance : distance;
}

double Ellipsoid::volume() const
{
  return 4.0 / 3.0 * M_PI * m_Radii.prod();
}

Bounds Ellipsoid::bounds() const
{
  // Support function of an ellipsoid along a unit vector n: |diag(radii) * R^T n|.
  Vector3 halfExtent;
  for (int k = 0; k < 3; ++k)
    halfExtent[k] = (m_Radii.asDiagonal() * m_Rotation.row(k).transpose()).norm();
  return { m_Center - halfExtent, m_Center + halfExtent };
}

} // namespace slicemesh

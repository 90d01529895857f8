#include "TubeTree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace slicemesh
{

double distanceToSegment(const Vector3& point, const Vector3& a, const Vector3& b)
{
  const Vector3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (point - (a + t * ab)).norm();
}

TubeTree::TubeTree(std::vector<Segment> segments, double radius)
  : m_Segments(std::move(segments))
  , m_Radius(radius)
{
  if (m_Segments.empty() || !(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("TubeTree: needs at least one segment and a positive radius");
  if (m_Segments.size() == 1)
  {
    const double length = (m_Segments[0].second - m_Segments[0].first).norm();
    m_Volume = M_PI * radius * radius * length + 4.0 / 3.0 * M_PI * radius * radius * radius;
    return;
  }
  // Midpoint rule over the bounds; each column's inside cells are counted.
  const Bounds b = bounds();
  const double h = radius / 24.0;
  const Vector3 extent = b.upper - b.lower;
  const int nx = static_cast<int>(std::ceil(extent.x() / h)), ny = static_cast<int>(std::ceil(extent.y() / h)),
            nz = static_cast<int>(std::ceil(extent.z() / h));
  std::size_t inside = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        inside += signedDistance(b.lower + h * Vector3(i + 0.5, j + 0.5, k + 0.5)) <= 0.0;
  m_Volume = static_cast<double>(inside) * h * h * h;
}

double TubeTree::signedDistance(const Vector3& point) const
{
  double nearest = std::numeric_limits<double>::infinity();
  for (const Segment& s : m_Segments)
    nearest = std::min(nearest, distanceToSegment(point, s.first, s.second));
  return nearest - m_Radius;
}

Bounds TubeTree::bounds() const
{
  Bounds b;
  b.lower = b.upper = m_Segments.front().first;
  for (const Segment& s : m_Segments)
  {
    b.lower = b.lower.cwiseMin(s.first).cwiseMin(s.second);
    b.upper = b.upper.cwiseMax(s.first).cwiseMax(s.second);
  }
  b.lower.array() -= m_Radius;
  b.upper.array() += m_Radius;
  return b;
}

} // namespace slicemesh

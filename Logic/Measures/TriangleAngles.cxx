#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

namespace
{

/** The angle at o between the edges to p and q. */
double angleAt(const Point3& o, const Point3& p, const Point3& q)
{
  const double ux = p.x - o.x, uy = p.y - o.y, uz = p.z - o.z;
  const double vx = q.x - o.x, vy = q.y - o.y, vz = q.z - o.z;
  const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz);
}

double squaredDistance(const Point3& a, const Point3& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  return dx * dx + dy * dy + dz * dz;
}

} // namespace

std::array<double, 3> triangleAngles(const Point3& a, const Point3& b, const Point3& c)
{
  return { angleAt(a, b, c), angleAt(b, c, a), angleAt(c, a, b) };
}

double smallestAngle(const Point3& a, const Point3& b, const Point3& c)
{
  // The corner opposite the shortest edge (law of sines): one arc tangent instead of three, in the
  // tiling's refinement and flips, which ask for it of every triangle, round after round.
  const double ab = squaredDistance(a, b), bc = squaredDistance(b, c), ca = squaredDistance(c, a);
  if (bc <= ca && bc <= ab)
    return angleAt(a, b, c);
  return ca <= ab ? angleAt(b, c, a) : angleAt(c, a, b);
}

double largestAngle(const Point3& a, const Point3& b, const Point3& c)
{
  // The corner opposite the longest edge.
  const double ab = squaredDistance(a, b), bc = squaredDistance(b, c), ca = squaredDistance(c, a);
  if (bc >= ca && bc >= ab)
    return angleAt(a, b, c);
  return ca >= ab ? angleAt(b, c, a) : angleAt(c, a, b);
}

bool angleUnder(double radians, double boundDegrees)
{
  return radians * 180.0 / M_PI < boundDegrees * (1.0 - 1e-12);
}

double smallestAngleCosine(const Point3& a, const Point3& b, const Point3& c)
{
  const Point3* p[3] = { &a, &b, &c };
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
  const double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
  if (!(std::sqrt(cx * cx + cy * cy + cz * cz) > 0.0))
    return 1.0;
  // The corner opposite the shortest edge.
  const double length2[3] = { squaredDistance(b, c), squaredDistance(c, a), squaredDistance(a, b) };
  const int k = length2[0] <= length2[1] ? (length2[0] <= length2[2] ? 0 : 2) : (length2[1] <= length2[2] ? 1 : 2);
  const Point3& o = *p[k];
  const Point3& q = *p[(k + 1) % 3];
  const Point3& r = *p[(k + 2) % 3];
  const double ax = q.x - o.x, ay = q.y - o.y, az = q.z - o.z, bx = r.x - o.x, by = r.y - o.y, bz = r.z - o.z;
  return (ax * bx + ay * by + az * bz) / std::sqrt(length2[(k + 2) % 3] * length2[(k + 1) % 3]);
}

SmallestAngleBound::SmallestAngleBound(double radians)
  : m_Radians(radians)
  , m_Cosine(std::cos(radians))
{
}

bool SmallestAngleBound::metBy(const Point3& a, const Point3& b, const Point3& c) const
{
  const double cosine = smallestAngleCosine(a, b, c);
  if (cosine < m_Cosine - smallestAngleCosineTie)
    return true;
  if (cosine > m_Cosine + smallestAngleCosineTie)
    return false;
  return smallestAngle(a, b, c) >= m_Radians;
}

} // namespace slicemesh

#include "Measures/MeshQuality.h"

#include "Core/ParallelFor.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace slicemesh
{
namespace
{

double length(const Point3& a, const Point3& b)
{
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/** Smallest and largest angle (radians, TriangleAngles.h) and aspect ratio (from the edge lengths) of
 *  triangle abc. */
struct Shape
{
  double smallest = 0.0, largest = 0.0, aspect = std::numeric_limits<double>::infinity();
};

Shape shapeOf(const Point3& a, const Point3& b, const Point3& c)
{
  const double la = length(b, c), lb = length(c, a), lc = length(a, b);
  // Heron's formula in its stable form (Kahan), lengths sorted x >= y >= z.
  double x = la, y = lb, z = lc;
  if (x < y)
    std::swap(x, y);
  if (y < z)
    std::swap(y, z);
  if (x < y)
    std::swap(x, y);
  const double product = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  const double area = 0.25 * std::sqrt(std::max(0.0, product));
  Shape shape;
  if (!(area > 0.0))
  {
    shape.largest = M_PI;
    return shape;
  }
  // The corners opposite the shortest and the longest edge (law of sines): two arc tangents, not three.
  shape.smallest = smallestAngle(a, b, c);
  shape.largest = largestAngle(a, b, c);
  const double s = 0.5 * (x + y + z);
  const double inradius = area / s;
  const double circumradius = x * y * z / (4.0 * area);
  shape.aspect = circumradius / (2.0 * inradius);
  return shape;
}

} // namespace

std::vector<double> triangleMinAngles(const TriangleMesh& mesh)
{
  std::vector<double> angles;
  angles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    angles.push_back(shapeOf(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]).smallest * 180.0 / M_PI);
  return angles;
}

MeshQuality measureMeshQuality(const TriangleMesh& mesh, unsigned int threads)
{
  MeshQuality q;
  q.triangles = mesh.triangles.size();
  if (mesh.triangles.empty())
    return q;
  // Ranges of triangles side by side (the measure ran on one thread at the end of a run while the
  // other cores waited); each range's sums added in range order, so the same whatever the threads.
  struct RangeShapes
  {
    double smallest = M_PI, largest = 0.0, aspectSum = 0.0;
    std::size_t below30 = 0, below10 = 0;
  };
  constexpr std::size_t trianglesPerRange = 16384;
  std::vector<double> aspects(mesh.triangles.size());
  const std::vector<RangeShapes> ranges = fixedRangeResults<RangeShapes>(
    mesh.triangles.size(), trianglesPerRange, threads,
    [&](RangeShapes& range, std::size_t first, std::size_t last)
    {
      for (std::size_t f = first; f < last; ++f)
      {
        const Triangle& t = mesh.triangles[f];
        const Shape shape = shapeOf(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
        range.smallest = std::min(range.smallest, shape.smallest);
        range.largest = std::max(range.largest, shape.largest);
        range.below30 += angleUnder(shape.smallest, 30.0);
        range.below10 += angleUnder(shape.smallest, 10.0);
        aspects[f] = shape.aspect;
        range.aspectSum += shape.aspect;
      }
    });
  double smallest = M_PI, largest = 0.0, aspectSum = 0.0;
  std::size_t below30 = 0, below10 = 0;
  for (const RangeShapes& range : ranges)
  {
    smallest = std::min(smallest, range.smallest);
    largest = std::max(largest, range.largest);
    below30 += range.below30;
    below10 += range.below10;
    aspectSum += range.aspectSum;
  }
  const double n = static_cast<double>(mesh.triangles.size());
  q.minAngleDegrees = smallest * 180.0 / M_PI;
  q.maxAngleDegrees = largest * 180.0 / M_PI;
  q.fractionBelow30 = below30 / n;
  q.fractionBelow10 = below10 / n;
  q.meanAspectRatio = aspectSum / n;
  // Three selections rather than a sort: the same order statistics in linear time.
  const auto at = [&aspects](std::size_t rank)
  {
    std::nth_element(aspects.begin(), aspects.begin() + static_cast<std::ptrdiff_t>(rank), aspects.end());
    return aspects[rank];
  };
  q.maxAspectRatio = at(aspects.size() - 1);
  q.p95AspectRatio = at(std::min(aspects.size() - 1, static_cast<std::size_t>(0.95 * n)));
  q.medianAspectRatio = at(aspects.size() / 2);
  return q;
}

long genusOf(const MeshValidation& validation)
{
  if (!validation.closed() || !validation.manifold() || validation.triangles == 0)
    return -1;
  const long twiceGenus = 2 * static_cast<long>(validation.components) - validation.eulerCharacteristic;
  return twiceGenus >= 0 && twiceGenus % 2 == 0 ? twiceGenus / 2 : -1;
}

} // namespace slicemesh

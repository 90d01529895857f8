// Axis-aligned bounding boxes of points, triangles and meshes: what the tests for crossing and
// nesting surfaces compare before any exact test.
#ifndef BoundingBox_h
#define BoundingBox_h

#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <array>
#include <limits>

namespace slicemesh
{

/** A closed box; empty (low above high) until a point is added. */
struct BoundingBox
{
  std::array<double, 3> low{ std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::max() };
  std::array<double, 3> high{ std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                              std::numeric_limits<double>::lowest() };

  void add(const Point3& p)
  {
    const std::array<double, 3> c{ p.x, p.y, p.z };
    for (int a = 0; a < 3; ++a)
    {
      low[a] = std::min(low[a], c[a]);
      high[a] = std::max(high[a], c[a]);
    }
  }

  void add(const BoundingBox& other)
  {
    for (int a = 0; a < 3; ++a)
    {
      low[a] = std::min(low[a], other.low[a]);
      high[a] = std::max(high[a], other.high[a]);
    }
  }

  /** Whether the two share a point: boxes that only touch overlap. */
  bool overlaps(const BoundingBox& other) const
  {
    for (int a = 0; a < 3; ++a)
      if (low[a] > other.high[a] || other.low[a] > high[a])
        return false;
    return true;
  }

  bool contains(const BoundingBox& other) const
  {
    for (int a = 0; a < 3; ++a)
      if (other.low[a] < low[a] || other.high[a] > high[a])
        return false;
    return true;
  }
};

/** The box of triangle t of the mesh. */
inline BoundingBox boxOfTriangle(const TriangleMesh& mesh, std::size_t t)
{
  BoundingBox box;
  for (std::int32_t v : mesh.triangles[t])
    box.add(mesh.points[static_cast<std::size_t>(v)]);
  return box;
}

/** The box of the mesh's triangles (its unused points left out). */
inline BoundingBox boxOfTriangles(const TriangleMesh& mesh)
{
  BoundingBox box;
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t)
      box.add(mesh.points[static_cast<std::size_t>(v)]);
  return box;
}

} // namespace slicemesh

#endif

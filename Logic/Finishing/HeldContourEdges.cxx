#include "Finishing/HeldContourEdges.h"

#include "Contours/ContourResampling.h"
#include "Core/PlanarGeometry.h"
#include "Core/SpatialHash.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{
namespace
{

/** The contour edges of one slice, in a spatial hash of their bounding boxes. */
struct SliceSegments
{
  explicit SliceSegments(const Slice& slice, double cell)
    : grid(cell)
  {
    for (const Polygon2& contour : slice.contours)
      for (std::size_t i = 0; i < contour.size(); ++i)
      {
        const Point2& a = contour[i];
        const Point2& b = contour[(i + 1) % contour.size()];
        grid.insert(grid.cellsOf(Box2{ std::min(a.x, b.x) - onContourTolerance, std::min(a.y, b.y) - onContourTolerance,
                                       std::max(a.x, b.x) + onContourTolerance,
                                       std::max(a.y, b.y) + onContourTolerance }),
                    static_cast<int>(segments.size()));
        segments.emplace_back(a, b);
      }
  }

  bool onContour(const Point2& p) const
  {
    const long long x = grid.cellOf(p.x), y = grid.cellOf(p.y);
    for (int s : grid.cell(x, y))
    {
      const auto& [a, b] = segments[static_cast<std::size_t>(s)];
      if (distanceToSegment(p, a, b) <= onContourTolerance)
        return true;
    }
    return false;
  }

  SpatialHash grid;
  std::vector<std::pair<Point2, Point2>> segments;
};

} // namespace

HeldContourEdges heldContourEdges(const TriangleMesh& mesh, const ContourStack& contours)
{
  HeldContourEdges held;
  held.vertices.assign(mesh.points.size(), 0);
  if (contours.slices.empty())
    return held;
  // The hash's cell: the mean contour edge (any positive size finds the same segments).
  const double meanEdge = meanPointSpacing(contours);
  const double cell = meanEdge > 0.0 ? meanEdge : 1.0;
  std::vector<SliceSegments> slices;
  std::vector<double> heights;
  for (const Slice& slice : contours.slices)
  {
    slices.emplace_back(slice, cell);
    heights.push_back(slice.z);
  }
  // The slice whose plane a point lies in, or -1 (slices are in increasing z).
  auto sliceOf = [&](double z) -> long
  {
    const auto above = std::lower_bound(heights.begin(), heights.end(), z - onContourTolerance);
    if (above == heights.end() || *above > z + onContourTolerance)
      return -1;
    return static_cast<long>(above - heights.begin());
  };
  std::vector<long> slice(mesh.points.size(), -1);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    const Point3& p = mesh.points[v];
    slice[v] = sliceOf(p.z);
    held.vertices[v] = slice[v] >= 0 && slices[static_cast<std::size_t>(slice[v])].onContour({ p.x, p.y });
    if (!held.vertices[v])
      slice[v] = -1;
  }
  // Each edge of a closed, oriented mesh is a directed edge of two triangles, once each way: taken
  // from its lower end.
  for (const Triangle& t : mesh.triangles)
    for (int corner = 0; corner < 3; ++corner)
    {
      const std::int32_t a = t[corner], b = t[(corner + 1) % 3];
      const long s = slice[static_cast<std::size_t>(a)];
      if (a > b || s < 0 || slice[static_cast<std::size_t>(b)] != s)
        continue;
      const Point3& p = mesh.points[static_cast<std::size_t>(a)];
      const Point3& q = mesh.points[static_cast<std::size_t>(b)];
      if (slices[static_cast<std::size_t>(s)].onContour({ 0.5 * (p.x + q.x), 0.5 * (p.y + q.y) }))
        held.edges.emplace_back(a, b);
    }
  // A vertex between exactly two contour edges, within onContourTolerance of the line through their
  // other ends and between them.
  std::vector<std::int32_t> count(mesh.points.size(), 0), first(mesh.points.size(), -1), second(mesh.points.size(), -1);
  for (const auto& [a, b] : held.edges)
    for (const auto& [v, u] : { std::pair{ a, b }, std::pair{ b, a } })
    {
      const auto i = static_cast<std::size_t>(v);
      (count[i] == 0 ? first[i] : second[i]) = u;
      ++count[i];
    }
  held.straight.assign(mesh.points.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    if (count[v] != 2)
      continue;
    const Point3& p = mesh.points[v];
    const Point3& a = mesh.points[static_cast<std::size_t>(first[v])];
    const Point3& b = mesh.points[static_cast<std::size_t>(second[v])];
    double t = 0.0;
    held.straight[v] = distanceToSegment({ p.x, p.y }, { a.x, a.y }, { b.x, b.y }, &t) <= onContourTolerance &&
                       t > 0.0 && t < 1.0;
  }
  return held;
}

} // namespace slicemesh

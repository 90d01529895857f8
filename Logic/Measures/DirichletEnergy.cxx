#include "Measures/DirichletEnergy.h"

#include "Core/PlanarGeometry.h"
#include "Measures/EdgeUses.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace slicemesh
{
namespace
{

Point2 xy(const Point3& p)
{
  return { p.x, p.y };
}

/** Projected area times |grad z|^2 of the linear interpolant on triangle abc (mm^2); 0 when the
 *  projection is degenerate. */
double triangleEnergy(const Point3& a, const Point3& b, const Point3& c)
{
  const double x1 = b.x - a.x, y1 = b.y - a.y, z1 = b.z - a.z;
  const double x2 = c.x - a.x, y2 = c.y - a.y, z2 = c.z - a.z;
  const double det = x1 * y2 - y1 * x2;
  if (det == 0.0)
    return 0.0;
  const double gx = (z1 * y2 - z2 * y1) / det;
  const double gy = (x1 * z2 - x2 * z1) / det;
  return 0.5 * std::abs(det) * (gx * gx + gy * gy);
}

} // namespace

DirichletEnergy measureDirichletEnergy(const TriangleMesh& mesh, const ContourStack& stack, double relativeTolerance)
{
  DirichletEnergy result;
  const std::vector<Slice>& slices = stack.slices;
  if (slices.size() < 2 || mesh.triangles.empty())
    return result;

  // Lengths in the stack set the tolerance for "at a slice's height" and "on a contour".
  double extent = 0.0;
  for (const Point3& p : mesh.points)
    extent = std::max({ extent, std::abs(p.x), std::abs(p.y), std::abs(p.z) });
  const double tolerance = 1e-7 * std::max(1.0, extent);

  // Slab of each triangle (-1: none) and whether it is sloped.
  auto sliceAt = [&](double z) -> long
  {
    auto it = std::lower_bound(slices.begin(), slices.end(), z - tolerance,
                               [](const Slice& s, double value) { return s.z < value; });
    if (it != slices.end() && std::abs(it->z - z) <= tolerance)
      return it - slices.begin();
    return -1;
  };
  std::vector<long> slabOf(mesh.triangles.size(), -1);
  std::vector<int> facing(mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    const Point3 &a = mesh.points[tri[0]], &b = mesh.points[tri[1]], &c = mesh.points[tri[2]];
    const double zmin = std::min({ a.z, b.z, c.z }), zmax = std::max({ a.z, b.z, c.z });
    if (zmax - zmin <= tolerance)
      continue; // level: a cap or a flat chord triangle
    const int turn = orientation(xy(a), xy(b), xy(c));
    const double projected = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    if (turn == 0 || projected <= tolerance * tolerance)
      continue; // vertical: a wall
    auto it = std::upper_bound(slices.begin(), slices.end(), zmin + tolerance,
                               [](double value, const Slice& s) { return value < s.z; });
    if (it == slices.begin() || it == slices.end())
      continue; // below the first or above the last slice: a cap
    const long k = (it - slices.begin()) - 1;
    if (zmin < slices[k].z - tolerance || zmax > slices[k + 1].z + tolerance)
      continue;
    slabOf[t] = k;
    facing[t] = turn;
    ++result.tilingTriangles;
    result.energy += triangleEnergy(a, b, c);
  }

  // A contour edge (a constraint) is an edge level at a slice's height: the tiling splits every other
  // chord between two points of one slice (Algorithm.md, step 6). Not the stack's own contour
  // segments: the tiling removes contour vertices next to crossing points (step 3).
  auto onContour = [&](const Point3& p, const Point3& q) -> bool
  { return std::abs(p.z - q.z) <= tolerance && sliceAt(p.z) >= 0; };

  const EdgeUses edges(mesh, 1); // on one thread: this measure runs beside the finishing
  auto visitEdge = [&](std::int32_t a, std::int32_t b, std::size_t t1, std::size_t t2)
  {
    if (slabOf[t1] < 0 || slabOf[t1] != slabOf[t2] || facing[t1] != facing[t2])
      return;
    auto opposite = [&](std::size_t t)
    {
      for (std::int32_t v : mesh.triangles[t])
        if (v != a && v != b)
          return v;
      return a;
    };
    const std::int32_t c = opposite(t1), d = opposite(t2);
    const Point3 &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c], &pd = mesh.points[d];
    if (onContour(pa, pb))
      return;
    // Strictly convex quad: c and d on opposite sides of ab, a and b on opposite sides of cd.
    if (orientation(xy(pa), xy(pb), xy(pc)) * orientation(xy(pa), xy(pb), xy(pd)) >= 0 ||
        orientation(xy(pc), xy(pd), xy(pa)) * orientation(xy(pc), xy(pd), xy(pb)) >= 0)
      return;
    if (edges.contains(c, d))
      return;
    ++result.flipCandidates;
    const double before = triangleEnergy(pa, pb, pc) + triangleEnergy(pa, pb, pd);
    const double after = triangleEnergy(pc, pd, pa) + triangleEnergy(pc, pd, pb);
    const double decrease = before - after;
    if (decrease > relativeTolerance * before && decrease > 0.0)
    {
      ++result.loweringFlips;
      result.largestDecrease = std::max(result.largestDecrease, decrease);
      result.largestRelativeDecrease = std::max(result.largestRelativeDecrease, decrease / before);
    }
  };
  for (std::size_t v = 0; v < edges.vertices(); ++v)
    edges.forEachEdgeOf(v,
                        [&](const EdgeUse* first, const EdgeUse* last)
                        {
                          if (last - first == 2) // an edge between two triangles
                            visitEdge(static_cast<std::int32_t>(v), first->other, first->triangle, first[1].triangle);
                        });
  return result;
}

} // namespace slicemesh

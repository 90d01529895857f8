#include "Finishing/SurfaceSmoothing.h"

#include "Core/ParallelFor.h"
#include "Measures/MeshComponents.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace slicemesh
{
namespace
{

/** The neighbours of every vertex (vertices sharing an edge with it), in compressed rows. */
struct VertexNeighbours
{
  std::vector<std::size_t> first; ///< neighbours of v are ids[first[v]] .. ids[first[v + 1]] - 1
  std::vector<std::int32_t> ids;
};

VertexNeighbours neighboursOf(const TriangleMesh& mesh)
{
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  edges.reserve(mesh.triangles.size() * 6);
  for (const Triangle& t : mesh.triangles)
    for (int corner = 0; corner < 3; ++corner)
    {
      edges.emplace_back(t[corner], t[(corner + 1) % 3]);
      edges.emplace_back(t[(corner + 1) % 3], t[corner]);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  VertexNeighbours neighbours;
  neighbours.first.assign(mesh.points.size() + 1, 0);
  neighbours.ids.reserve(edges.size());
  for (const auto& [from, to] : edges)
  {
    ++neighbours.first[static_cast<std::size_t>(from) + 1];
    neighbours.ids.push_back(to);
  }
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    neighbours.first[v + 1] += neighbours.first[v];
  return neighbours;
}

/** p += factor * (mean of the neighbours - p), for every vertex at once. */
void umbrellaStep(std::vector<Point3>& points, const VertexNeighbours& neighbours, double factor,
                  std::vector<Point3>& scratch, unsigned int threads)
{
  parallelForRanges(points.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        const std::size_t begin = neighbours.first[v], end = neighbours.first[v + 1];
                        scratch[v] = points[v];
                        if (begin == end)
                          continue;
                        double x = 0.0, y = 0.0, z = 0.0;
                        for (std::size_t i = begin; i < end; ++i)
                        {
                          const Point3& q = points[static_cast<std::size_t>(neighbours.ids[i])];
                          x += q.x;
                          y += q.y;
                          z += q.z;
                        }
                        const double count = static_cast<double>(end - begin);
                        scratch[v].x += factor * (x / count - points[v].x);
                        scratch[v].y += factor * (y / count - points[v].y);
                        scratch[v].z += factor * (z / count - points[v].z);
                      }
                    });
  points.swap(scratch);
}

/** Twice the area times the unit normal of triangle t (the cross product of two of its edges). */
Point3 areaNormal(const TriangleMesh& mesh, const Triangle& t)
{
  const Point3& a = mesh.points[t[0]];
  const Point3& b = mesh.points[t[1]];
  const Point3& c = mesh.points[t[2]];
  return { (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y), (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z),
           (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) };
}

/** Signed volume and area of every component (by the component of each triangle's first vertex). */
void measureComponents(const TriangleMesh& mesh, const std::vector<std::size_t>& component, std::vector<double>& volume,
                       std::vector<double>& area)
{
  std::fill(volume.begin(), volume.end(), 0.0);
  std::fill(area.begin(), area.end(), 0.0);
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 n = areaNormal(mesh, t);
    const Point3& a = mesh.points[t[0]];
    const std::size_t k = component[static_cast<std::size_t>(t[0])];
    volume[k] += (a.x * n.x + a.y * n.y + a.z * n.z) / 6.0;
    area[k] += 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  }
}

/** Unit vertex normals: the sum of the area-weighted normals of the vertex's triangles. */
std::vector<Point3> vertexNormals(const TriangleMesh& mesh)
{
  std::vector<Point3> normals(mesh.points.size());
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 n = areaNormal(mesh, t);
    for (std::int32_t v : t)
    {
      normals[v].x += n.x;
      normals[v].y += n.y;
      normals[v].z += n.z;
    }
  }
  for (Point3& n : normals)
  {
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (length > 0.0)
      n = { n.x / length, n.y / length, n.z / length };
  }
  return normals;
}

/** Gives every component back the signed volume it had (`target`) by moving its vertices along their
 *  normals by one common distance (a few Newton steps: the volume grows by the area per unit of
 *  offset). Taubin's filter keeps large shapes, but shrinks a structure a few edges across, whose
 *  whole shape lies above the pass band: a vessel two voxels wide would lose half its volume. */
void restoreVolumes(TriangleMesh& mesh, const std::vector<std::size_t>& component, const std::vector<double>& target)
{
  std::vector<double> volume(target.size()), area(target.size()), offset(target.size());
  for (int step = 0; step < 4; ++step)
  {
    measureComponents(mesh, component, volume, area);
    bool done = true;
    for (std::size_t k = 0; k < target.size(); ++k)
    {
      offset[k] = area[k] > 0.0 ? (target[k] - volume[k]) / area[k] : 0.0;
      done = done && std::abs(target[k] - volume[k]) <= 1e-9 * std::abs(target[k]);
    }
    if (done)
      return;
    const std::vector<Point3> normals = vertexNormals(mesh);
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
    {
      const double d = offset[component[v]];
      mesh.points[v].x += d * normals[v].x;
      mesh.points[v].y += d * normals[v].y;
      mesh.points[v].z += d * normals[v].z;
    }
  }
}

/** Pulls every point that has left the ellipsoid of semi-axes `bound` around its start back onto it,
 *  along its displacement. */
void clampDisplacements(std::vector<Point3>& points, const std::vector<Point3>& start, const std::array<double, 3>& bound)
{
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    const double dx = points[v].x - start[v].x, dy = points[v].y - start[v].y, dz = points[v].z - start[v].z;
    // The displacement in units of the bound: 1 on the ellipsoid.
    const double reach = std::sqrt((dx / bound[0]) * (dx / bound[0]) + (dy / bound[1]) * (dy / bound[1]) +
                                   (dz / bound[2]) * (dz / bound[2]));
    if (reach > 1.0)
    {
      const double f = 1.0 / reach;
      points[v] = { start[v].x + f * dx, start[v].y + f * dy, start[v].z + f * dz };
    }
  }
}

} // namespace

void offsetToVolume(TriangleMesh& mesh, double volume)
{
  if (mesh.triangles.empty())
    return;
  restoreVolumes(mesh, std::vector<std::size_t>(mesh.points.size(), 0), { volume });
}

void smoothSurface(TriangleMesh& mesh, const SurfaceSmoothingOptions& options, unsigned int threads)
{
  if (options.iterations <= 0 || mesh.triangles.empty())
    return;
  if (!(options.passBand > 0.0 && options.passBand < 1.0))
    throw Error("surface smoothing: the pass band must lie between 0 and 1");
  const double lambda = 0.5;
  const double mu = 1.0 / (options.passBand - 1.0 / lambda);
  std::size_t components = 0;
  const std::vector<std::size_t> component = vertexComponents(mesh, components);
  std::vector<double> volume(components), area(components);
  measureComponents(mesh, component, volume, area);

  const VertexNeighbours neighbours = neighboursOf(mesh);
  std::vector<Point3> scratch(mesh.points.size());
  const std::vector<Point3> start = mesh.points;
  const bool bounded = std::any_of(options.maxDisplacement.begin(), options.maxDisplacement.end(),
                                   [](double axis) { return axis > 0.0; });
  if (bounded && !std::all_of(options.maxDisplacement.begin(), options.maxDisplacement.end(),
                              [](double axis) { return axis > 0.0 && std::isfinite(axis); }))
    throw Error("surface smoothing: the displacement bound must be positive along every axis, or 0 along all");
  for (int i = 0; i < options.iterations; ++i)
  {
    umbrellaStep(mesh.points, neighbours, lambda, scratch, threads);
    umbrellaStep(mesh.points, neighbours, mu, scratch, threads);
    if (bounded)
      clampDisplacements(mesh.points, start, options.maxDisplacement);
  }
  // A component a few edges across has no shape below the pass band: the filter collapses it, and
  // no offset can give a speck its volume back. Such a component keeps its unsmoothed vertices.
  std::vector<double> smoothedVolume(components), smoothedArea(components);
  measureComponents(mesh, component, smoothedVolume, smoothedArea);
  std::vector<bool> collapsed(components);
  for (std::size_t k = 0; k < components; ++k)
    collapsed[k] = !(smoothedArea[k] > 0.0 && smoothedVolume[k] * volume[k] > 0.0 &&
                     std::abs(smoothedVolume[k]) >= 0.5 * std::abs(volume[k]));
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (collapsed[component[v]])
      mesh.points[v] = start[v];
  restoreVolumes(mesh, component, volume);
}

} // namespace slicemesh

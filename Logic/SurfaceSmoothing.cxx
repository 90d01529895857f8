#include "SurfaceSmoothing.h"

#include <algorithm>
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
                  std::vector<Point3>& scratch)
{
  for (std::size_t v = 0; v < points.size(); ++v)
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
  points.swap(scratch);
}

} // namespace

void smoothSurface(TriangleMesh& mesh, const SurfaceSmoothingOptions& options)
{
  if (options.iterations <= 0 || mesh.triangles.empty())
    return;
  if (!(options.passBand > 0.0 && options.passBand < 1.0))
    throw Error("surface smoothing: the pass band must lie between 0 and 1");
  const double lambda = 0.5;
  const double mu = 1.0 / (options.passBand - 1.0 / lambda);
  const VertexNeighbours neighbours = neighboursOf(mesh);
  std::vector<Point3> scratch(mesh.points.size());
  for (int i = 0; i < options.iterations; ++i)
  {
    umbrellaStep(mesh.points, neighbours, lambda, scratch);
    umbrellaStep(mesh.points, neighbours, mu, scratch);
  }
}

} // namespace slicemesh

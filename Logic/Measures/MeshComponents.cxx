#include "Measures/MeshComponents.h"

#include "Core/DisjointSets.h"

#include <algorithm>

namespace slicemesh
{

std::vector<std::size_t> vertexComponents(const TriangleMesh& mesh, std::size_t& count)
{
  DisjointSets sets(mesh.points.size());
  for (const Triangle& t : mesh.triangles)
  {
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]));
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[2]));
  }
  const std::size_t none = mesh.points.size();
  std::vector<std::size_t> numberOfRoot(mesh.points.size(), none);
  count = 0;
  for (const Triangle& t : mesh.triangles)
  {
    const std::size_t root = sets.find(static_cast<std::size_t>(t[0]));
    if (numberOfRoot[root] == none)
      numberOfRoot[root] = count++;
  }
  std::vector<std::size_t> component(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    const std::size_t root = sets.find(v);
    if (numberOfRoot[root] == none)
      numberOfRoot[root] = count++;
    component[v] = numberOfRoot[root];
  }
  return component;
}

void growByRings(const TriangleMesh& mesh, std::vector<char>& marked, int rings)
{
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> grown = marked;
    for (const Triangle& t : mesh.triangles)
      if (marked[static_cast<std::size_t>(t[0])] || marked[static_cast<std::size_t>(t[1])] ||
          marked[static_cast<std::size_t>(t[2])])
        for (std::int32_t v : t)
          grown[static_cast<std::size_t>(v)] = 1;
    marked.swap(grown);
  }
}

std::vector<TriangleMesh> splitIntoPieces(const TriangleMesh& mesh)
{
  std::size_t count = 0;
  const std::vector<std::size_t> component = vertexComponents(mesh, count);
  // Components with triangles come first; a vertex in no triangle makes no piece.
  std::size_t withTriangles = 0;
  for (const Triangle& t : mesh.triangles)
    withTriangles = std::max(withTriangles, component[static_cast<std::size_t>(t[0])] + 1);
  std::vector<TriangleMesh> pieces(withTriangles);
  // Each piece's arrays at their size from the start: grown by doubling, those of a piece of a
  // million triangles held up to twice their size at a run's peak.
  std::vector<std::size_t> points(withTriangles, 0), triangles(withTriangles, 0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (component[v] < withTriangles)
      ++points[component[v]];
  for (const Triangle& t : mesh.triangles)
    ++triangles[component[static_cast<std::size_t>(t[0])]];
  for (std::size_t p = 0; p < withTriangles; ++p)
  {
    pieces[p].points.reserve(points[p]);
    pieces[p].triangles.reserve(triangles[p]);
  }
  std::vector<std::int32_t> newIndex(mesh.points.size(), -1);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (component[v] < withTriangles)
    {
      TriangleMesh& piece = pieces[component[v]];
      newIndex[v] = static_cast<std::int32_t>(piece.points.size());
      piece.points.push_back(mesh.points[v]);
    }
  for (const Triangle& t : mesh.triangles)
    pieces[component[static_cast<std::size_t>(t[0])]].triangles.push_back(
      { newIndex[t[0]], newIndex[t[1]], newIndex[t[2]] });
  return pieces;
}


void appendMesh(TriangleMesh& joined, const TriangleMesh& mesh)
{
  const auto offset = static_cast<std::int32_t>(joined.points.size());
  joined.points.insert(joined.points.end(), mesh.points.begin(), mesh.points.end());
  for (const Triangle& t : mesh.triangles)
    joined.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
}

TriangleMesh appendedPart(const TriangleMesh& joined, AppendedAt from, AppendedAt to)
{
  TriangleMesh part;
  part.points.assign(joined.points.begin() + static_cast<std::ptrdiff_t>(from.point),
                     joined.points.begin() + static_cast<std::ptrdiff_t>(to.point));
  const auto offset = static_cast<std::int32_t>(from.point);
  part.triangles.reserve(to.triangle - from.triangle);
  for (std::size_t t = from.triangle; t < to.triangle; ++t)
  {
    const Triangle& corners = joined.triangles[t];
    part.triangles.push_back({ corners[0] - offset, corners[1] - offset, corners[2] - offset });
  }
  return part;
}

TriangleMesh joinMeshes(const std::vector<const TriangleMesh*>& meshes, std::vector<std::size_t>* firstTriangle)
{
  TriangleMesh joined;
  if (firstTriangle)
    firstTriangle->clear();
  for (const TriangleMesh* mesh : meshes)
  {
    if (firstTriangle)
      firstTriangle->push_back(joined.triangles.size());
    appendMesh(joined, *mesh);
  }
  return joined;
}

} // namespace slicemesh

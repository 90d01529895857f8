#include "MeshComponents.h"

#include "DisjointSets.h"

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

} // namespace slicemesh

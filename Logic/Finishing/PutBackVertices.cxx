#include "Finishing/PutBackVertices.h"

#include "Measures/MeshComponents.h"

namespace slicemesh
{
namespace
{

/** Puts back where `unsmoothed` (the mesh's points before smoothing) has them the vertices of every
 *  triangle in a crossing pair and `rings` rings of triangles around them, flagging them in
 *  `movedBack`. Returns how many vertices moved back. */
std::size_t unsmoothAround(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed,
                           const std::vector<std::pair<std::size_t, std::size_t>>& crossings, int rings,
                           std::vector<char>& movedBack)
{
  std::vector<char> marked(mesh.points.size(), 0);
  for (const auto& [first, second] : crossings)
    for (std::size_t t : { first, second })
      for (std::int32_t v : mesh.triangles[t])
        marked[static_cast<std::size_t>(v)] = 1;
  growByRings(mesh, marked, rings);
  return unsmooth(mesh, unsmoothed, marked, &movedBack);
}

} // namespace

std::vector<char> movedVertices(const std::vector<Point3>& before, const std::vector<Point3>& after)
{
  std::vector<char> moved(before.size(), 0);
  for (std::size_t v = 0; v < before.size(); ++v)
    moved[v] = !samePoint(before[v], after[v]);
  return moved;
}

std::size_t unsmooth(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed, const std::vector<char>& marked,
                     std::vector<char>* movedBack)
{
  std::size_t moved = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (marked[v] && !samePoint(mesh.points[v], unsmoothed[v]))
    {
      mesh.points[v] = unsmoothed[v];
      ++moved;
      if (movedBack)
        (*movedBack)[v] = 1;
    }
  return moved;
}

std::size_t unsmoothCrossings(TriangleMesh& mesh, const std::vector<Point3>& unsmoothed, MeshValidation& validation,
                              std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  std::size_t moved = 0;
  for (int rings = 1; rings <= 4 && validation.selfIntersections > 0; rings *= 2)
  {
    std::vector<char> movedBack(mesh.points.size(), 0);
    moved += unsmoothAround(mesh, unsmoothed, crossings, rings, movedBack);
    validation = validateMeshAfterMovingPoints(mesh, validation, movedBack, crossings);
  }
  return moved;
}

} // namespace slicemesh

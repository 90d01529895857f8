#include "Measures/ComponentOrientation.h"

#include "Core/BoundingBox.h"
#include "Core/MeetingBoxes.h"
#include "Core/ParallelFor.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Measures/TriangleMeshTree.h"

#include <CGAL/Polygon_mesh_processing/internal/Side_of_triangle_mesh/Point_inside_vertical_ray_cast.h>

#include <algorithm>
#include <memory>
#include <utility>

namespace slicemesh
{
namespace
{

using Kernel = CgalKernel;
/** CGAL's inside/outside test (what its Side_of_triangle_mesh runs), over a tree of the component's
 *  own triangles (TriangleMeshTree). */
using RayParity = CGAL::internal::Point_inside_vertical_ray_cast<Kernel, TriangleMeshTree>;

/** A component held for inside/outside queries (CGAL's ray parity over an AABB tree, which shoots
 *  again when a ray grazes an edge; asked only of points inside the component's box). The tree is
 *  built here, not at the first query (the queries of several threads would wait for it), and on
 *  the component itself: making a copy of it in CGAL's mesh was a fifth of the time. The component
 *  must outlive it. */
struct Enclosure
{
  TriangleMeshTree tree;

  explicit Enclosure(const TriangleMesh& mesh)
  {
    insertTriangles(tree, mesh);
    tree.build();
  }

  bool encloses(const Point3& p) const
  {
    return RayParity()(Kernel::Point_3(p.x, p.y, p.z), tree) == CGAL::ON_BOUNDED_SIDE;
  }
};

} // namespace

std::size_t misorientedComponents(const std::vector<const TriangleMesh*>& components, const std::vector<double>& volumes,
                                  unsigned int threads)
{
  const std::size_t n = components.size();
  if (n == 1)
    return volumes.front() > 0.0 ? 0 : 1;
  std::vector<BoundingBox> boxes;
  boxes.reserve(n);
  for (const TriangleMesh* c : components)
    boxes.push_back(boxOfTriangles(*c));
  // Surfaces that do not cross nest only if their boxes do: most components nest in none, and only
  // a component whose box holds another's needs a tree. (A component without triangles has an
  // empty box, which meets none.)
  std::vector<std::vector<std::size_t>> enclosing(n); // per component, those whose box holds its own
  std::vector<char> needed(n, 0);
  for (const auto& [i, j] : meetingBoxes(boxes))
    for (const auto& [b, a] : { std::pair(i, j), std::pair(j, i) })
      if (boxes[b].contains(boxes[a]))
      {
        enclosing[a].push_back(b);
        needed[b] = 1;
      }
  std::vector<std::unique_ptr<Enclosure>> enclosures(n);
  parallelFor(n, threads,
              [&](std::size_t b)
              {
                if (needed[b])
                  enclosures[b] = std::make_unique<Enclosure>(*components[b]);
              });
  std::vector<char> misoriented(n, 0);
  parallelFor(n, threads,
              [&](std::size_t a)
              {
                const TriangleMesh& component = *components[a];
                if (component.triangles.empty())
                  return;
                const Point3& probe = component.points[static_cast<std::size_t>(component.triangles.front()[0])];
                std::size_t depth = 0;
                for (std::size_t b : enclosing[a])
                  depth += enclosures[b]->encloses(probe);
                const bool outward = depth % 2 == 0;
                misoriented[a] = outward ? !(volumes[a] > 0.0) : !(volumes[a] < 0.0);
              });
  return static_cast<std::size_t>(std::count(misoriented.begin(), misoriented.end(), 1));
}

std::size_t misorientedComponents(const TriangleMesh& mesh)
{
  const std::vector<TriangleMesh> components = splitIntoPieces(mesh);
  if (components.empty())
    return 0;
  std::vector<const TriangleMesh*> pointers;
  std::vector<double> volumes;
  for (const TriangleMesh& c : components)
  {
    pointers.push_back(&c);
    volumes.push_back(signedVolume(c));
  }
  return misorientedComponents(pointers, volumes, 0); // on every core, as the rest of the topology check
}

} // namespace slicemesh

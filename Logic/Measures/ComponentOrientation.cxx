#include "Measures/ComponentOrientation.h"

#include "Core/BoundingBox.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Measures/SurfaceMeshConversion.h"

#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <memory>

namespace slicemesh
{
namespace
{

using Kernel = CgalKernel;
using SurfaceMesh = CgalSurfaceMesh;
using SideOf = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;

/** A component held for inside/outside queries (CGAL's ray parity over an AABB tree, which shoots
 *  again when a ray grazes an edge). */
struct Enclosure
{
  SurfaceMesh surface;
  std::unique_ptr<SideOf> side;

  explicit Enclosure(const TriangleMesh& mesh)
  {
    if (toSurfaceMesh(mesh, surface) != mesh.triangles.size())
      throw Error("component orientation: a component is not a manifold surface");
    side = std::make_unique<SideOf>(surface);
  }

  bool encloses(const Point3& p) const { return (*side)(Kernel::Point_3(p.x, p.y, p.z)) == CGAL::ON_BOUNDED_SIDE; }
};

} // namespace

std::size_t misorientedComponents(const std::vector<const TriangleMesh*>& components, const std::vector<double>& volumes)
{
  const std::size_t n = components.size();
  if (n == 1)
    return volumes.front() > 0.0 ? 0 : 1;
  std::vector<BoundingBox> boxes;
  boxes.reserve(n);
  for (const TriangleMesh* c : components)
    boxes.push_back(boxOfTriangles(*c));
  // Most components nest in none: the boxes rule them out before any tree is built.
  std::vector<std::unique_ptr<Enclosure>> enclosures(n);
  std::size_t misoriented = 0;
  for (std::size_t a = 0; a < n; ++a)
  {
    const TriangleMesh& component = *components[a];
    if (component.triangles.empty())
      continue;
    const Point3& probe = component.points[static_cast<std::size_t>(component.triangles.front()[0])];
    std::size_t depth = 0;
    for (std::size_t b = 0; b < n; ++b)
    {
      // Surfaces that do not cross nest only if their boxes do.
      if (b == a || components[b]->triangles.empty() || !boxes[b].contains(boxes[a]))
        continue;
      if (!enclosures[b])
        enclosures[b] = std::make_unique<Enclosure>(*components[b]);
      depth += enclosures[b]->encloses(probe);
    }
    const bool outward = depth % 2 == 0;
    misoriented += outward ? !(volumes[a] > 0.0) : !(volumes[a] < 0.0);
  }
  return misoriented;
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
  return misorientedComponents(pointers, volumes);
}

} // namespace slicemesh

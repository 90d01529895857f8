#include "Measures/ComponentOrientation.h"

#include "Core/BoundingBox.h"
#include "Core/MeetingBoxes.h"
#include "Core/ParallelFor.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Measures/PointsInside.h"

#include <utility>

namespace slicemesh
{
namespace
{

/** Components of this many triangles are asked one at a time, each on every thread. */
constexpr std::size_t largeComponent = 1 << 16;

const Point3& firstVertex(const TriangleMesh& component)
{
  return component.points[static_cast<std::size_t>(component.triangles.front()[0])];
}

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
  // a component whose box holds another's is asked. (A component without triangles has an empty
  // box, which meets none.)
  std::vector<std::vector<std::size_t>> enclosing(n); // per component, those whose box holds its own
  std::vector<char> needed(n, 0);
  for (const auto& [i, j] : meetingBoxes(boxes))
    for (const auto& [b, a] : { std::pair(i, j), std::pair(j, i) })
      if (boxes[b].contains(boxes[a]))
      {
        enclosing[a].push_back(b);
        needed[b] = 1;
      }
  // Each component that holds another's box is asked, in one pass over its triangles, which of
  // those components' first vertices it encloses: the large ones one after another on every
  // thread, the small ones side by side. (A vertex on the other surface itself, where two
  // components touch, is decided by the ray's perturbation; such touching is a crossing, which the
  // self-intersection tests report.)
  std::vector<std::vector<std::size_t>> held(n); // per component, those whose box its box holds
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b : enclosing[a])
      held[b].push_back(a);
  std::vector<std::size_t> holders;
  for (std::size_t b = 0; b < n; ++b)
    if (needed[b])
      holders.push_back(b);
  std::vector<std::vector<char>> inside(n);
  largeOnesFirst(
    holders, threads, [&](std::size_t b) { return components[b]->triangles.size() >= largeComponent; },
    [&](std::size_t b, unsigned int askThreads)
    {
      std::vector<Point3> probes;
      for (std::size_t a : held[b])
        probes.push_back(firstVertex(*components[a]));
      inside[b] = pointsInside(*components[b], probes, askThreads);
    });
  std::vector<std::size_t> depth(n, 0);
  for (std::size_t b = 0; b < n; ++b)
    for (std::size_t k = 0; k < held[b].size(); ++k)
      depth[held[b][k]] += static_cast<std::size_t>(inside[b][k]);
  std::size_t misoriented = 0;
  for (std::size_t a = 0; a < n; ++a)
    if (!components[a]->triangles.empty())
      misoriented += depth[a] % 2 == 0 ? !(volumes[a] > 0.0) : !(volumes[a] < 0.0);
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
  return misorientedComponents(pointers, volumes, 0); // on every core, as the rest of the topology check
}

} // namespace slicemesh

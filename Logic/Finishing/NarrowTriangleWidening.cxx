#include "Finishing/NarrowTriangleWidening.h"

#include "Finishing/CrossingRepair.h"
#include "Finishing/PieceRejection.h"
#include "Measures/MeshComponents.h"
#include "Measures/TriangleAngles.h"

#include <cmath>

namespace slicemesh
{
namespace
{

/** The smallest angle the widening aims at (degrees): the quality measure's threshold. */
constexpr double narrowAngle = 30.0;

/** The vertices the widening may change: the corners of the triangles under narrowAngle and of the
 *  triangles around them (a flip of a narrow triangle's edge rewrites its neighbour too), except the
 *  `fixed` ones. Only these, not the whole piece: the repair's set-up (its scope two rings around
 *  them) and the check of what changed then grow with the narrow triangles, not with the piece (the
 *  large scaling ellipsoid, a few narrow triangles among 860,000, ran a fifth longer with 60 MB more
 *  when the whole piece was movable). Empty if no triangle is under narrowAngle. */
std::vector<char> widenableVertices(const TriangleMesh& mesh, const std::vector<char>& fixed)
{
  const SmallestAngleBound wide(narrowAngle * M_PI / 180.0);
  std::vector<char> widenable(mesh.points.size(), 0); // the narrow triangles' corners, then a ring more
  bool any = false;
  for (const Triangle& t : mesh.triangles)
  {
    const auto corner = [&](int i) -> const Point3& { return mesh.points[static_cast<std::size_t>(t[i])]; };
    if (!wide.metBy(corner(0), corner(1), corner(2)))
    {
      for (std::int32_t v : t)
        widenable[static_cast<std::size_t>(v)] = 1;
      any = true;
    }
  }
  if (!any)
    return {};
  growByRings(mesh, widenable, 1);
  if (!fixed.empty() && fixed.size() != mesh.points.size())
    throw Error("narrow triangle widening: the fixed vertices' flags do not match the mesh");
  for (std::size_t v = 0; v < fixed.size(); ++v)
    widenable[v] = widenable[v] && !fixed[v];
  return widenable;
}

} // namespace

std::size_t widenNarrowTriangles(TriangleMesh& mesh, MeshValidation& validation, const std::vector<char>& fixed,
                                 double edgeLength)
{
  if (!validation.valid() || !(validation.fractionAnglesBelow30 > 0.0))
    return 0; // most pieces: nothing to widen, and nothing set up
  const std::vector<char> widenable = widenableVertices(mesh, fixed);
  if (widenable.empty())
    return 0;
  TriangleMesh widened = mesh;
  const CrossingRepair widening = widenNarrowTrianglesLocally(widened, widenable, edgeLength, narrowAngle);
  if (widening.operations() == 0)
    return 0;
  // Elsewhere than at the corners of the triangles the widening made or removed, the piece is as it
  // was, valid: the validation gathers the edges and tests the crossings around those corners only.
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  const MeshValidation after = validateMeshAfterLocalChange(widened, validation, widening.changed, crossings);
  if (!rejection(after, validation).empty())
    return 0;
  mesh = std::move(widened);
  validation = after;
  return widening.operations();
}

} // namespace slicemesh

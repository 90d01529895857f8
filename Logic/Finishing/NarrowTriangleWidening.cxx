#include "Finishing/NarrowTriangleWidening.h"

#include "Finishing/CrossingRepair.h"
#include "Finishing/PieceRejection.h"
#include "Finishing/PutBackVertices.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace slicemesh
{
namespace
{

/** The smallest angle the widening aims at (degrees): the quality measure's threshold. */
constexpr double narrowAngle = 30.0;

/** A triangle's corners turned to start at the smallest: the same triangle, facing the same way,
 *  whatever corner it was written from. */
Triangle canonical(Triangle t)
{
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

/** The vertices the widening may change: the corners of the triangles under narrowAngle and of the
 *  triangles around them (a flip of a narrow triangle's edge rewrites its neighbour too), except the
 *  `fixed` ones. Only these, not the whole piece: the repair's set-up (its scope two rings around
 *  them) and the check of what changed then grow with the narrow triangles, not with the piece (the
 *  large scaling ellipsoid, a few narrow triangles among 860,000, ran a fifth longer with 60 MB more
 *  when the whole piece was movable). Empty if no triangle is under narrowAngle. */
std::vector<char> widenableVertices(const TriangleMesh& mesh, const std::vector<char>& fixed)
{
  const SmallestAngleBound wide(narrowAngle * M_PI / 180.0);
  std::vector<char> narrowCorner(mesh.points.size(), 0);
  bool any = false;
  for (const Triangle& t : mesh.triangles)
  {
    const auto corner = [&](int i) -> const Point3& { return mesh.points[static_cast<std::size_t>(t[i])]; };
    if (!wide.metBy(corner(0), corner(1), corner(2)))
    {
      for (std::int32_t v : t)
        narrowCorner[static_cast<std::size_t>(v)] = 1;
      any = true;
    }
  }
  if (!any)
    return {};
  std::vector<char> widenable = narrowCorner;
  for (const Triangle& t : mesh.triangles)
    if (narrowCorner[static_cast<std::size_t>(t[0])] || narrowCorner[static_cast<std::size_t>(t[1])] ||
        narrowCorner[static_cast<std::size_t>(t[2])])
      for (std::int32_t v : t)
        widenable[static_cast<std::size_t>(v)] = 1;
  if (!fixed.empty() && fixed.size() != mesh.points.size())
    throw Error("narrow triangle widening: the fixed vertices' flags do not match the mesh");
  for (std::size_t v = 0; v < fixed.size(); ++v)
    widenable[v] = widenable[v] && !fixed[v];
  return widenable;
}

/** The vertices of `widened` (numbered as the repair left them) on triangles that `before` did not
 *  have, by their corners' former numbers and points: those of the flipped and collapsed edges, the
 *  only ones whose triangles can cross anything they did not cross before. Every triangle an
 *  operation makes has a `widenable` corner (the ends of a flipped or collapsed edge), so only
 *  those are looked up. */
std::vector<char> verticesOfNewTriangles(const TriangleMesh& before, const TriangleMesh& widened,
                                         const CrossingRepair& widening, const std::vector<char>& widenable)
{
  const auto touches = [&](const Triangle& t)
  {
    return widenable[static_cast<std::size_t>(t[0])] || widenable[static_cast<std::size_t>(t[1])] ||
           widenable[static_cast<std::size_t>(t[2])];
  };
  std::set<Triangle> had;
  for (const Triangle& t : before.triangles)
    if (touches(t))
      had.insert(canonical(t));
  std::vector<char> changed(widened.points.size(), 0);
  for (const Triangle& t : widened.triangles)
  {
    Triangle former{};
    bool moved = false;
    for (int i = 0; i < 3; ++i)
    {
      const auto v = static_cast<std::size_t>(t[i]);
      former[i] = widening.formerVertex[v];
      moved = moved || !samePoint(widened.points[v], before.points[static_cast<std::size_t>(former[i])]);
    }
    if (moved || (touches(former) && !had.count(canonical(former))))
      for (std::int32_t v : t)
        changed[static_cast<std::size_t>(v)] = 1;
  }
  return changed;
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
  std::vector<std::pair<std::size_t, std::size_t>> crossings; // the piece crossed nothing before
  const MeshValidation after = validateMeshAfterMoving(widened, validation.selfIntersectionChecked,
                                                       verticesOfNewTriangles(mesh, widened, widening, widenable), crossings);
  if (!rejection(after, validation).empty())
    return 0;
  mesh = std::move(widened);
  validation = after;
  return widening.operations();
}

} // namespace slicemesh

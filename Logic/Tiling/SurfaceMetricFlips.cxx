// Step 8 of Documentation/Algorithm.md, second half: Lawson flips towards the largest smallest angle
// of the lifted triangles, so the tiling is Delaunay-like in the surface's own metric.
#include "Tiling/SlabOverlayState.h"

#include "Core/AreaNormal.h"
#include "Core/PlanarGeometry.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace slicemesh
{

using namespace slab;

namespace
{

/** Cosine of the angle between the normals of triangles (a, b, c) and (b, a, d), which share edge
 *  ab: 1 where they are coplanar, -1 where one folds onto the other. */
double normalsCosine(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  const Point3 m = areaNormal(a, b, c), n = areaNormal(b, a, d);
  const double lengths = std::sqrt((m.x * m.x + m.y * m.y + m.z * m.z) * (n.x * n.x + n.y * n.y + n.z * n.z));
  return lengths > 0.0 ? (m.x * n.x + m.y * n.y + m.z * n.z) / lengths : 1.0;
}

} // namespace

std::size_t SlabOverlay::Impl::flipTowardsSurfaceQuality(const MeshBuilder& mesh, const std::vector<VertexHandle>* around,
                                                         std::vector<VertexHandle>* touched)
{
  // The planar CDT minimises the Dirichlet energy of the height field (Rippa), but where the surface
  // climbs steeply between nearly parallel contours its triangles are slivers in 3D: Delaunay in
  // the plane is not Delaunay on the lifted surface. Lawson flips with the max-min angle criterion
  // measured on the lifted triangles make the tiling Delaunay-like in the surface's own metric.
  // A flip is taken only where the quad is convex in projection (the surface stays a height field,
  // so no triangle can cross another) and never at a vertex common to both slices or into a chord
  // flat on a slice plane (the invariants of the switch fans and of the neighbouring slabs).
  auto lifted = [&](VertexHandle v) -> Point3 {
    const OverlayVertex& ov = vertices[v->info()];
    if (ov.isSteiner())
      return mesh.point(ov.steinerId);
    return { ov.p.x, ov.p.y, ov.lowerId >= 0 ? z0 : z1 };
  };
  auto flippable = [&](FaceHandle f, int i) {
    if (f->is_constrained(i) || cdt.is_infinite(f) || cdt.is_infinite(f->neighbor(i)) || !isDifference(f))
      return false;
    FaceHandle g = f->neighbor(i);
    const VertexHandle a = f->vertex(i), b = g->vertex(cdt.mirror_index(f, i));
    const VertexHandle p = f->vertex(CDT::cw(i)), q = f->vertex(CDT::ccw(i));
    for (VertexHandle v : { a, b, p, q })
      if (vertices[v->info()].onBoth())
        return false;
    const Level la = singleLevel(vertices[a->info()]), lb = singleLevel(vertices[b->info()]);
    if (la != NoLevel && la == lb)
      return false;
    const Point2 pa{ a->point().x(), a->point().y() }, pb{ b->point().x(), b->point().y() };
    const Point2 pp{ p->point().x(), p->point().y() }, pq{ q->point().x(), q->point().y() };
    if (orientation(pa, pb, pp) * orientation(pa, pb, pq) >= 0)
      return false;
    // Nor into a triangle of almost no width in projection: lifted, it stands vertical, which the 3D
    // angles like, but a neighbour can fold onto it (and rounding later make them cross).
    if (distanceToSegment(pp, pa, pb) < 1e-3 * typicalEdge || distanceToSegment(pq, pa, pb) < 1e-3 * typicalEdge)
      return false;
    const Point3 A = lifted(a), B = lifted(b), P = lifted(p), Q = lifted(q);
    // The smallest angles compared by their cosines first (smallestAngleCosineTie: outside a near
    // tie they decide as the angles would, the margin below included), without the arc tangents,
    // which were most of this pass.
    const double cosineBefore = std::max(smallestAngleCosine(A, P, Q), smallestAngleCosine(B, Q, P));
    const double cosineAfter = std::max(smallestAngleCosine(A, B, Q), smallestAngleCosine(B, A, P));
    if (cosineAfter > cosineBefore + smallestAngleCosineTie)
      return false;
    // Nor into a crease sharper than a right angle across the new edge: steep triangles have good
    // angles, but two of them meeting in a knife-edge ridge nearly fold onto each other.
    const double crease = normalsCosine(A, B, Q, P);
    if (crease < 0.0 && crease < normalsCosine(P, Q, A, B))
      return false;
    if (cosineAfter < cosineBefore - smallestAngleCosineTie)
      return true;
    const double before = std::min(smallestAngle(A, P, Q), smallestAngle(B, Q, P));
    const double after = std::min(smallestAngle(A, B, Q), smallestAngle(B, A, P));
    return after > before + 1e-9;
  };
  // The worst triangles' edges are taken first (the queue pops from the back): the flips then settle
  // in a better local optimum than in mesh order.
  std::vector<std::pair<double, CDT::Edge>> ranked;
  // Each face's angle once per ranking, not once for each of its edges (the arc tangents were a
  // third of this pass); no face changes while the edges are ranked.
  const std::uint32_t ranking = ++flipRankings;
  auto rankedAngle = [&](FaceHandle f) {
    FaceData& data = f->info();
    if (data.rankedIn != ranking)
    {
      data.rankedAngle = smallestAngle(lifted(f->vertex(0)), lifted(f->vertex(1)), lifted(f->vertex(2)));
      data.rankedIn = ranking;
    }
    return data.rankedAngle;
  };
  // Away from a change every edge was left where no flip improves it: only the edges around the
  // change are looked at first (the refinement's rounds, which insert a few points each).
  for (const CDT::Edge& e : around ? finiteEdgesAround(cdt, *around) : finiteEdgesInStableOrder(cdt))
    if (!e.first->is_constrained(e.second) && isDifference(e.first) && !cdt.is_infinite(e.first->neighbor(e.second)))
      ranked.emplace_back(std::min(rankedAngle(e.first), rankedAngle(e.first->neighbor(e.second))), e);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<std::pair<VertexHandle, VertexHandle>> queue;
  for (const auto& [worst, e] : ranked)
    queue.emplace_back(e.first->vertex(CDT::cw(e.second)), e.first->vertex(CDT::ccw(e.second)));
  std::size_t flips = 0;
  const std::size_t limit = 20 * queue.size() + 100;
  while (!queue.empty() && flips < limit)
  {
    const auto [u, v] = queue.back();
    queue.pop_back();
    FaceHandle f;
    int i = 0;
    if (!cdt.is_edge(u, v, f, i) || !flippable(f, i))
      continue;
    FaceHandle g = f->neighbor(i);
    const VertexHandle a = f->vertex(i), b = g->vertex(cdt.mirror_index(f, i));
    cdt.flip(f, i);
    ++flips;
    if (touched)
      touched->insert(touched->end(), { a, b, u, v });
    for (VertexHandle w : { u, v })
    {
      queue.emplace_back(a, w);
      queue.emplace_back(b, w);
    }
  }
  if (!queue.empty())
    flipsSettled = false;
  return flips;
}

} // namespace slicemesh

#include "Finishing/RemeshingPasses.h"

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <vector>

namespace slicemesh
{
namespace
{

using Mesh = CgalSurfaceMesh;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;
using Edge = Mesh::Edge_index;
using Point = CgalKernel::Point_3;
using Vector = CgalKernel::Vector_3;

double squaredLength(const Mesh& mesh, Halfedge h)
{
  return CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
}

/** An edge waiting in a heap, by its squared length when it was put there. */
struct Waiting
{
  double squaredLength;
  Halfedge halfedge;
};

/** Longest first; of equal lengths, the lower halfedge first (the order depends on the mesh only). */
struct ShorterFirstOut
{
  bool operator()(const Waiting& a, const Waiting& b) const
  {
    return a.squaredLength < b.squaredLength || (a.squaredLength == b.squaredLength && a.halfedge > b.halfedge);
  }
};

/** Shortest first; of equal lengths, the lower halfedge first. */
struct LongerFirstOut
{
  bool operator()(const Waiting& a, const Waiting& b) const
  {
    return a.squaredLength > b.squaredLength || (a.squaredLength == b.squaredLength && a.halfedge > b.halfedge);
  }
};

/** Whether the entry still stands for its edge as it is: not removed, not changed in length. */
bool current(const Mesh& mesh, const Waiting& w)
{
  return !mesh.is_removed(mesh.edge(w.halfedge)) && squaredLength(mesh, w.halfedge) == w.squaredLength;
}

bool constrainedOrBorder(const Mesh& mesh, const ConstrainedEdges& constrained, Edge e)
{
  return constrained[e] || mesh.is_border(e);
}

/** A vertex on a constrained edge (or the mesh's border) stays where it is. */
bool held(const Mesh& mesh, const ConstrainedEdges& constrained, Vertex v)
{
  for (Halfedge h : CGAL::halfedges_around_target(v, mesh))
    if (constrainedOrBorder(mesh, constrained, mesh.edge(h)))
      return true;
  return false;
}

/** Whether h is at least as long as the other edges of its two triangles. A split of anything
 *  shorter next to a constrained edge could split again forever. */
bool longestOfItsTriangles(const Mesh& mesh, Halfedge h)
{
  const double length = squaredLength(mesh, h);
  for (Halfedge side : { h, mesh.opposite(h) })
  {
    if (mesh.is_border(side))
      continue;
    if (squaredLength(mesh, mesh.next(side)) > length || squaredLength(mesh, mesh.prev(side)) > length)
      return false;
  }
  return true;
}

void splitLongEdges(Mesh& mesh, const ConstrainedEdges& constrained, bool hasConstraints, double high)
{
  const double squaredHigh = high * high;
  std::priority_queue<Waiting, std::vector<Waiting>, ShorterFirstOut> waiting;
  auto wait = [&](Halfedge h)
  {
    const double length = squaredLength(mesh, h);
    if (length > squaredHigh)
      waiting.push({ length, h });
  };
  for (Edge e : mesh.edges())
    if (!constrainedOrBorder(mesh, constrained, e))
      wait(mesh.halfedge(e));
  while (!waiting.empty())
  {
    const Waiting w = waiting.top();
    waiting.pop();
    if (!current(mesh, w))
      continue;
    const Halfedge h = w.halfedge;
    if (hasConstraints && !longestOfItsTriangles(mesh, h))
      continue;
    const Point middle = CGAL::midpoint(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
    // hnew runs from h's source to the new vertex, h from there on.
    const Halfedge hnew = CGAL::Euler::split_edge(h, mesh);
    mesh.point(mesh.target(hnew)) = middle;
    constrained[mesh.edge(hnew)] = false;
    wait(hnew);
    wait(h);
    // The triangles on either side are split from the new vertex to their third corner.
    if (!mesh.is_border(hnew))
    {
      const Halfedge diagonal = CGAL::Euler::split_face(hnew, mesh.next(mesh.next(hnew)), mesh);
      constrained[mesh.edge(diagonal)] = false;
      wait(diagonal);
    }
    const Halfedge opposite = mesh.opposite(hnew);
    if (!mesh.is_border(opposite))
    {
      const Halfedge diagonal = CGAL::Euler::split_face(mesh.prev(opposite), mesh.next(opposite), mesh);
      constrained[mesh.edge(diagonal)] = false;
      wait(diagonal);
    }
  }
}

/** Whether collapsing h's source into its target would turn a triangle around the source over or
 *  leave it without area (the two triangles on h excepted, which go). */
bool collapseSpoilsATriangle(const Mesh& mesh, Halfedge h)
{
  const Vertex s = mesh.source(h), t = mesh.target(h);
  const Point& ps = mesh.point(s);
  const Point& pt = mesh.point(t);
  for (Halfedge around : CGAL::halfedges_around_target(mesh.opposite(h), mesh))
  {
    if (mesh.is_border(around))
      continue;
    const Vertex a = mesh.target(mesh.next(around)), b = mesh.target(mesh.next(mesh.next(around)));
    if (a == t || b == t)
      continue;
    const Point& pa = mesh.point(a);
    const Point& pb = mesh.point(b);
    if (CGAL::collinear(pt, pa, pb))
      return true;
    if (CGAL::collinear(ps, pa, pb))
      continue; // no direction before: nothing to turn over
    const Vector before = CGAL::cross_product(Vector(ps, pa), Vector(ps, pb));
    const Vector after = CGAL::cross_product(Vector(pt, pa), Vector(pt, pb));
    if (!(before * after > 0.0))
      return true;
  }
  return false;
}

/** Whether the triangle of these three vertices would lie flat on a slice: all three on contours,
 *  at one height. */
bool flatOnContour(const Mesh& mesh, const ContourVertices* contour, Vertex a, Vertex b, Vertex c)
{
  return contour && contour->onContour[a] && contour->onContour[b] && contour->onContour[c] &&
         mesh.point(a).z() == mesh.point(b).z() && mesh.point(b).z() == mesh.point(c).z();
}

/** Whether collapsing h's source into its target would leave a triangle flat on a slice
 *  (flatOnContour) that was not. */
bool collapseFlattens(const Mesh& mesh, Halfedge h, const ContourVertices* contour)
{
  if (!contour || !contour->onContour[mesh.target(h)])
    return false;
  const Vertex s = mesh.source(h), t = mesh.target(h);
  for (Halfedge around : CGAL::halfedges_around_target(mesh.opposite(h), mesh))
  {
    if (mesh.is_border(around))
      continue;
    const Vertex a = mesh.target(mesh.next(around)), b = mesh.target(mesh.next(mesh.next(around)));
    if (a != t && b != t && flatOnContour(mesh, contour, t, a, b) && !flatOnContour(mesh, contour, s, a, b))
      return true;
  }
  return false;
}

void collapseShortEdges(Mesh& mesh, const ConstrainedEdges& constrained, double low, double high,
                        const ContourVertices* contour)
{
  const double squaredLow = low * low, squaredHigh = high * high;
  // Found once: a collapse never removes a held vertex nor makes one held (of the two edges it
  // merges, the constrained one is kept, and it already touched the vertex kept).
  std::vector<char> heldVertex(mesh.num_vertices(), 0);
  for (Vertex v : mesh.vertices())
    heldVertex[v.idx()] = held(mesh, constrained, v);
  auto isHeld = [&](Vertex v) { return heldVertex[v.idx()] != 0; };
  // A constrained edge from a sliding vertex goes into its other end: the line stays as it was.
  auto slides = [&](Halfedge h)
  {
    return contour && constrained[mesh.edge(h)] && !mesh.is_border(mesh.edge(h)) &&
           (contour->sliding[mesh.source(h)] || contour->sliding[mesh.target(h)]);
  };
  auto collapseAllowed = [&](Halfedge h)
  {
    return slides(h) ||
           (!constrainedOrBorder(mesh, constrained, mesh.edge(h)) && !(isHeld(mesh.source(h)) && isHeld(mesh.target(h))));
  };
  std::priority_queue<Waiting, std::vector<Waiting>, LongerFirstOut> waiting;
  auto wait = [&](Halfedge h)
  {
    const double length = squaredLength(mesh, h);
    if (length < squaredLow && collapseAllowed(h))
      waiting.push({ length, h });
  };
  for (Edge e : mesh.edges())
    wait(mesh.halfedge(e));
  while (!waiting.empty())
  {
    const Waiting w = waiting.top();
    waiting.pop();
    if (!current(mesh, w) || !collapseAllowed(w.halfedge))
      continue;
    // h's source goes into its target: a held vertex stays.
    Halfedge h = w.halfedge;
    const bool sourceHeld = isHeld(mesh.source(h)), targetHeld = isHeld(mesh.target(h));
    const bool alongLine = slides(h);
    if (alongLine ? !contour->sliding[mesh.source(h)] : sourceHeld)
      h = mesh.opposite(h);
    const bool eitherWay = !alongLine && !sourceHeld && !targetHeld;
    // Whether an edge to the source's neighbours would grow past 4/3 of the target. The cheapest
    // test, first where the direction is settled (most short edges fail it).
    auto tooLong = [&](Halfedge into)
    {
      const Point& kept = mesh.point(mesh.target(into));
      for (Vertex neighbour : CGAL::vertices_around_target(mesh.halfedge(mesh.source(into)), mesh))
        if (CGAL::squared_distance(kept, mesh.point(neighbour)) > squaredHigh)
          return true;
      return false;
    };
    if (!eitherWay && tooLong(h))
      continue;
    auto spoils = [&](Halfedge into) { return collapseSpoilsATriangle(mesh, into) || collapseFlattens(mesh, into, contour); };
    if (spoils(h))
    {
      if (!eitherWay || spoils(mesh.opposite(h)))
        continue;
      h = mesh.opposite(h);
    }
    if ((eitherWay && tooLong(h)) || !CGAL::Euler::does_satisfy_link_condition(mesh.edge(h), mesh))
      continue;
    const Vertex kept = mesh.target(h);
    if (alongLine)
      constrained[mesh.edge(h)] = false; // it goes; CGAL's collapse takes no constrained edge
    // Merging the two edges of each removed triangle, the constrained one is the one kept.
    CGAL::Euler::collapse_edge(mesh.edge(h), mesh, constrained);
    for (Halfedge around : CGAL::halfedges_around_target(kept, mesh))
      wait(around);
  }
}

/** The cosine of the largest angle of a triangle over which it is a cap (160 degrees), and the
 *  ratio of its longest to its shortest edge over which it is a needle. */
const double capCosine = std::cos(160.0 * M_PI / 180.0);
constexpr double needleRatio = 4.0;

/** Whether the triangle of h is a needle or a cap whose long edge may be flipped: then a flip of
 *  any of its edges is taken whatever it does to the valences. */
bool badlyShaped(const Mesh& mesh, const ConstrainedEdges& constrained, Halfedge h)
{
  const Halfedge sides[3] = { h, mesh.next(h), mesh.prev(h) };
  double squared[3];
  for (int i = 0; i < 3; ++i)
    squared[i] = squaredLength(mesh, sides[i]);
  const double longest = std::max({ squared[0], squared[1], squared[2] });
  const double shortest = std::min({ squared[0], squared[1], squared[2] });
  if (longest > needleRatio * needleRatio * shortest)
    return true;
  // The angle opposite side i, between the two other sides, by the law of cosines.
  for (int i = 0; i < 3; ++i)
  {
    const double b = squared[(i + 1) % 3], c = squared[(i + 2) % 3];
    if (b > 0.0 && c > 0.0 && (b + c - squared[i]) / (2.0 * std::sqrt(b * c)) < capCosine)
      return !constrained[mesh.edge(sides[i])];
  }
  return false;
}

/** Whether the quad around h is better split by its other diagonal: the two triangles' area
 *  normals agree more (larger dot product), which avoids skinny triangles and folds alike. */
bool otherDiagonalBetter(const Mesh& mesh, Halfedge h)
{
  const Point& p0 = mesh.point(mesh.target(h));
  const Point& p1 = mesh.point(mesh.target(mesh.next(h)));
  const Point& p2 = mesh.point(mesh.source(h));
  const Point& p3 = mesh.point(mesh.target(mesh.next(mesh.opposite(h))));
  const Vector v01(p0, p1), v12(p1, p2), v23(p2, p3), v30(p3, p0);
  const double splitAt13 = CGAL::cross_product(v12, v23) * CGAL::cross_product(v30, v01);
  const double splitAt02 = CGAL::cross_product(v01, -v12) * CGAL::cross_product(v23, -v30);
  return splitAt02 <= splitAt13;
}

/** Whether the triangles around v, each against the one before it that has area, face the same
 *  side (positive dot product of their normals). */
bool unfoldedAround(const Mesh& mesh, Vertex v)
{
  Vector previous = CGAL::NULL_VECTOR;
  for (Halfedge h : CGAL::halfedges_around_target(v, mesh))
  {
    if (mesh.is_border(h))
      continue;
    const Vector n = areaNormal(mesh, h);
    if (n == CGAL::NULL_VECTOR)
      continue;
    if (previous != CGAL::NULL_VECTOR && !(n * previous > 0.0))
      return false;
    previous = n;
  }
  return true;
}

bool degenerateAround(const Mesh& mesh, Vertex v)
{
  for (Halfedge h : CGAL::halfedges_around_target(v, mesh))
    if (!mesh.is_border(h) &&
        CGAL::collinear(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h)))))
      return true;
  return false;
}

/** Whether the constraints let e be flipped. */
bool flipAllowed(const Mesh& mesh, const ConstrainedEdges& constrained, Edge e)
{
  if (constrainedOrBorder(mesh, constrained, e))
    return false;
  const Halfedge h = mesh.halfedge(e), o = mesh.opposite(h);
  // Two constrained edges meeting the edge at one end would be left with a triangle between them.
  for (Halfedge side : { h, o })
    if (constrained[mesh.edge(mesh.next(side))] && constrained[mesh.edge(mesh.prev(mesh.opposite(side)))])
      return false;
  return true;
}

/** Flips h (it then runs between the two vertices opposite it), and flips it back when that folds
 *  the two triangles onto each other or leaves a degenerate or folded triangle around its ends.
 *  Whether the flip stayed. */
bool flipKeepingShape(Mesh& mesh, Halfedge h)
{
  CGAL::Euler::flip_edge(h, mesh);
  if (!(areaNormal(mesh, h) * areaNormal(mesh, mesh.opposite(h)) > 0.0) || degenerateAround(mesh, mesh.target(h)) ||
      degenerateAround(mesh, mesh.source(h)) || !unfoldedAround(mesh, mesh.target(h)) ||
      !unfoldedAround(mesh, mesh.source(h)))
  {
    CGAL::Euler::flip_edge(h, mesh);
    return false;
  }
  return true;
}

/** Whether the other diagonal of the quad around h is an edge already (a flip would double it).
 *  A walk around a vertex: asked last, of the edges every other test let through. */
bool otherDiagonalExists(const Mesh& mesh, Halfedge h)
{
  return CGAL::halfedge(mesh.target(mesh.next(h)), mesh.target(mesh.next(mesh.opposite(h))), mesh).second;
}

void flipForValence(Mesh& mesh, const ConstrainedEdges& constrained, const ContourVertices* contour)
{
  std::vector<int> valence(mesh.num_vertices(), 0);
  for (Halfedge h : mesh.halfedges())
    ++valence[mesh.target(h).idx()];
  auto deviation = [](int a, int b, int c, int d)
  { return std::abs(a - 6) + std::abs(b - 6) + std::abs(c - 6) + std::abs(d - 6); };
  for (Edge e : mesh.edges())
  {
    if (!flipAllowed(mesh, constrained, e) || !otherDiagonalBetter(mesh, mesh.halfedge(e)))
      continue;
    const Halfedge h = mesh.halfedge(e);
    const Vertex a = mesh.source(h), b = mesh.target(h);
    const Vertex c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(mesh.opposite(h)));
    int& va = valence[a.idx()];
    int& vb = valence[b.idx()];
    int& vc = valence[c.idx()];
    int& vd = valence[d.idx()];
    // A flip for shape is taken whatever the valences; one for valence only if they improve.
    const bool forValence = deviation(va - 1, vb - 1, vc + 1, vd + 1) < deviation(va, vb, vc, vd);
    if (!forValence && !badlyShaped(mesh, constrained, h) && !badlyShaped(mesh, constrained, mesh.opposite(h)))
      continue;
    if (flatOnContour(mesh, contour, c, d, a) || flatOnContour(mesh, contour, c, d, b) || otherDiagonalExists(mesh, h))
      continue;
    if (!flipKeepingShape(mesh, h))
      continue;
    --va;
    --vb;
    ++vc;
    ++vd;
  }
}

/** The angle at c of the triangle a b c (radians). */
double angleAt(const Point& c, const Point& a, const Point& b)
{
  const Vector u(c, a), v(c, b);
  const double lengths = std::sqrt(u.squared_length() * v.squared_length());
  return lengths > 0.0 ? std::acos(std::clamp(u * v / lengths, -1.0, 1.0)) : 0.0;
}

/** Flips, sweep after sweep (a few), the edges that are not locally Delaunay (the angles opposite
 *  them sum to more than 180 degrees) between two triangles within coplanarDegrees of each other,
 *  where the constraints allow and no triangle around turns over. Around a drawn contour the
 *  valence flips leave the narrow triangles that a contour edge the passes may not touch makes
 *  with a vertex beside it; flipped to Delaunay they widen. Only nearly flat quads: a flip across
 *  a fold (a box's edge between two slices) would cut it. */
void flipToDelaunay(Mesh& mesh, const ConstrainedEdges& constrained, const ContourVertices* contour)
{
  constexpr double coplanarDegrees = 20.0;
  const double coplanarCosine = std::cos(coplanarDegrees * M_PI / 180.0);
  for (int sweep = 0; sweep < 3; ++sweep)
  {
    bool flipped = false;
    for (Edge e : mesh.edges())
    {
      if (!flipAllowed(mesh, constrained, e))
        continue;
      const Halfedge h = mesh.halfedge(e);
      const Point& a = mesh.point(mesh.source(h));
      const Point& b = mesh.point(mesh.target(h));
      const Point& c = mesh.point(mesh.target(mesh.next(h)));
      const Point& d = mesh.point(mesh.target(mesh.next(mesh.opposite(h))));
      if (angleAt(c, a, b) + angleAt(d, a, b) <= M_PI + 1e-9)
        continue;
      const Vector n = areaNormal(mesh, h), m = areaNormal(mesh, mesh.opposite(h));
      const Vertex vc = mesh.target(mesh.next(h)), vd = mesh.target(mesh.next(mesh.opposite(h)));
      if (!(n * m > coplanarCosine * std::sqrt(n.squared_length() * m.squared_length())) ||
          flatOnContour(mesh, contour, vc, vd, mesh.source(h)) || flatOnContour(mesh, contour, vc, vd, mesh.target(h)) ||
          otherDiagonalExists(mesh, h))
        continue;
      if (!flipKeepingShape(mesh, h))
        continue;
      flipped = true;
    }
    if (!flipped)
      break;
  }
}

} // namespace

CgalKernel::Vector_3 areaNormal(const CgalSurfaceMesh& mesh, CgalSurfaceMesh::Halfedge_index h)
{
  const Point& a = mesh.point(mesh.source(h));
  const Point& b = mesh.point(mesh.target(h));
  const Point& c = mesh.point(mesh.target(mesh.next(h)));
  return CGAL::cross_product(Vector(a, b), Vector(a, c));
}

void splitCollapseFlip(CgalSurfaceMesh& surface, const ConstrainedEdges& constrained, double targetEdgeLength,
                       const ContourVertices* contour)
{
  const double low = 0.8 * targetEdgeLength, high = 4.0 / 3.0 * targetEdgeLength;
  bool hasConstraints = false;
  for (Edge e : surface.edges())
    hasConstraints = hasConstraints || constrainedOrBorder(surface, constrained, e);
  splitLongEdges(surface, constrained, hasConstraints, high);
  collapseShortEdges(surface, constrained, low, high, contour);
  flipForValence(surface, constrained, contour);
  if (contour) // drawn contours held
    flipToDelaunay(surface, constrained, contour);
}

} // namespace slicemesh

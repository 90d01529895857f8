#include "Tiling/SlabTiling.h"

#include "Core/NearestSegment.h"
#include "Core/PlanarGeometry.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <map>
#include <sstream>
#include <unordered_map>

namespace slicemesh
{

namespace
{

// Which slice a lifted point belongs to.
enum Level : signed char
{
  NoLevel = -1,
  LowerLevel = 0,
  UpperLevel = 1
};

struct FaceData
{
  bool visited = false;
  bool inLower = false;
  bool inUpper = false;
  int lowerInnermost = -1; ///< innermost lower contour containing the face
  int upperInnermost = -1;
  int component = -1;      ///< difference polygon the face belongs to, -1 outside the symmetric difference
  std::array<signed char, 3> cornerLevel{ NoLevel, NoLevel, NoLevel }; ///< for corners on both slices
  std::array<std::int32_t, 3> lifted{ -1, -1, -1 };                   ///< mesh ids, in output winding
  std::array<std::int32_t, 3> cornerId{ -1, -1, -1 }; ///< chain node taken by a corner where the surface switches slices
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase =
  CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<FaceData, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using VertexHandle = CDT::Vertex_handle;
using FaceHandle = CDT::Face_handle;

/** A point of the projected overlay: a vertex of the lower slice, of the upper slice, of both
 *  (the slices meet there), or a Steiner point inside a difference polygon. */
struct OverlayVertex
{
  Point2 p;
  std::int32_t lowerId = -1; ///< mesh id on the lower slice
  std::int32_t upperId = -1;
  std::int32_t steinerId = -1;
  bool onBoth() const { return lowerId >= 0 && upperId >= 0; }
  bool isSteiner() const { return steinerId >= 0; }
};

/** What an overlay edge is: part of a lower contour, an upper contour, or both. `from` is the
 *  endpoint the contour leaves from (its solid lies to the left). */
struct OverlayEdge
{
  bool lower = false;
  bool upper = false;
  int lowerFrom = -1;
  int upperFrom = -1;
  int lowerContour = -1;
  int upperContour = -1;
};

std::uint64_t edgeKey(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/** A difference polygon: a connected piece of (lower \ upper) or (upper \ lower). */
struct Component
{
  bool lowerSide = false; ///< part of lower \ upper: the surface over it has the solid below
  bool touchesLowerLevel = false;
  bool touchesUpperLevel = false;
  bool isCap() const { return touchesLowerLevel != touchesUpperLevel; }
  Level capLevel() const { return touchesLowerLevel ? LowerLevel : UpperLevel; }
};

/** Faces around a vertex between two consecutive contour edges, in counter-clockwise order. */
struct Sector
{
  VertexHandle vertex;
  std::vector<FaceHandle> faces;
  std::vector<VertexHandle> fan; ///< far ends of the interior edges between consecutive faces
  Level startLevel = NoLevel;
  Level endLevel = NoLevel;
};

double minAngle3(const Point3& a, const Point3& b, const Point3& c)
{
  auto angle = [](const Point3& o, const Point3& p, const Point3& q) {
    const double ux = p.x - o.x, uy = p.y - o.y, uz = p.z - o.z;
    const double vx = q.x - o.x, vy = q.y - o.y, vz = q.z - o.z;
    const double cross = std::sqrt(std::pow(uy * vz - uz * vy, 2) + std::pow(uz * vx - ux * vz, 2) +
                                   std::pow(ux * vy - uy * vx, 2));
    return std::atan2(cross, ux * vx + uy * vy + uz * vz);
  };
  return std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) });
}

/** Cosine of the angle between the normals of triangles (a, b, c) and (b, a, d), which share edge
 *  ab: 1 where they are coplanar, -1 where one folds onto the other. */
double normalsCosine(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  auto normal = [](const Point3& p, const Point3& q, const Point3& r) {
    const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
    const double vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
    return std::array<double, 3>{ uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx };
  };
  const auto m = normal(a, b, c), n = normal(b, a, d);
  const double lengths = std::sqrt((m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
  return lengths > 0.0 ? (m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) / lengths : 1.0;
}

/** The finite edges, each once, in an order that depends only on the triangulation. CGAL's edge
 *  iterator reports an edge from whichever of its two faces lies at the lower address, so its
 *  order (and the face an edge is seen from) changed from run to run with the heap's layout; the
 *  order of flips and Steiner points, and so the mesh, changed with it. Here an edge is seen from
 *  the face in which it runs from the lower vertex id to the higher one (or from its only finite face). */
std::vector<CDT::Edge> finiteEdgesInStableOrder(const CDT& cdt)
{
  std::vector<CDT::Edge> edges;
  edges.reserve(3 * cdt.number_of_faces());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i)
      if (cdt.is_infinite(f->neighbor(i)) || f->vertex(CDT::cw(i))->info() < f->vertex(CDT::ccw(i))->info())
        edges.emplace_back(f, i);
  return edges;
}

class SpacingGrid; // below, after the Impl whose refinement uses it

} // namespace

struct SlabOverlay::Impl
{
  const PreparedSlice* lower = nullptr;
  const PreparedSlice* upper = nullptr;
  double z0 = 0.0;
  double z1 = 0.0;
  double tolerance = 0.0;

  std::vector<OverlayVertex> vertices;
  std::unordered_map<std::uint64_t, OverlayEdge> edges;
  CDT cdt;
  std::vector<Component> components;
  std::vector<char> lowerContinues, upperContinues;
  std::vector<std::pair<int, int>> correspondences;

  // Segments of each slice, for the distance interpolation of Steiner heights.
  std::vector<std::pair<Point2, Point2>> lowerSegments, upperSegments;
  std::unique_ptr<NearestSegment> lowerNearest, upperNearest;
  double typicalEdge = 1.0;

  // Height of the flat cap over each cap component, recomputed with the components.
  std::vector<double> capZ;
  const SlabLiftOptions* liftOptions = nullptr;

  void buildVertices();
  void buildEdges();
  void triangulate();
  void classify();
  std::vector<Sector> sectorsAround(VertexHandle v);
  Level edgeLevel(const OverlayEdge& e, bool lowerSide) const
  {
    if (lowerSide)
      return e.lower ? LowerLevel : UpperLevel;
    return e.upper ? UpperLevel : LowerLevel;
  }
  const OverlayEdge* edgeBetween(VertexHandle a, VertexHandle b) const
  {
    auto it = edges.find(edgeKey(a->info(), b->info()));
    return it == edges.end() ? nullptr : &it->second;
  }
  bool isDifference(FaceHandle f) const { return !cdt.is_infinite(f) && f->info().component >= 0; }
  bool inMixed(FaceHandle f) const { return isDifference(f) && !components[f->info().component].isCap(); }
  Level singleLevel(const OverlayVertex& v) const
  {
    if (v.isSteiner() || v.onBoth())
      return NoLevel;
    return v.lowerId >= 0 ? LowerLevel : UpperLevel;
  }
  double interpolatedHeight(const Point2& p) const;
  std::vector<Sector> mixedSectors(bool assignCornerLevels);
  std::size_t liftFlatChords(MeshBuilder& mesh);
  void computeCapHeights();
  bool isCapFace(FaceHandle f) const { return isDifference(f) && components[f->info().component].isCap(); }
  double capLevelZ(int component) const { return components[component].capLevel() == LowerLevel ? z0 : z1; }
  double domeHeight(int component, const Point2& p) const;
  double steinerHeight(FaceHandle f, const Point2& p) const
  {
    return isCapFace(f) ? domeHeight(f->info().component, p) : interpolatedHeight(p);
  }
  /** Faces whose chords must not lie flat on a slice plane: mixed ones, and domed caps. */
  bool needsLiftedChords(FaceHandle f) const
  {
    return inMixed(f) || (isCapFace(f) && capZ[f->info().component] != capLevelZ(f->info().component));
  }
  std::size_t addCapRows(MeshBuilder& mesh, double edgeLength);
  Point3 approximateLift(FaceHandle f, int i, const MeshBuilder& mesh) const;
  bool insertSteiner(const Point2& p, double z, MeshBuilder& mesh, double clearance = 0.0);
  /** Optional Steiner points keep this far (in 3D) from every contour (mm): closer, their triangles
   *  are slivers. */
  double optionalClearance() const { return 0.1 * typicalEdge; }
  std::size_t addRows(MeshBuilder& mesh, double edgeLength);
  /** The lifted corners of the difference faces: new Steiner points keep their distance from them. */
  void addLiftedCorners(SpacingGrid& placed, const MeshBuilder& mesh) const;
  /** Inserts each candidate (point, height) whose face `accepts` takes, with the optional clearance;
   *  classifies the faces again if any went in. */
  std::size_t insertCandidates(const std::vector<std::pair<Point2, double>>& candidates, MeshBuilder& mesh,
                               const std::function<bool(FaceHandle)>& accepts);
  std::size_t refineBadTriangles(MeshBuilder& mesh, double minAngle, double edgeLength, std::size_t budget);
  std::size_t flipTowardsSurfaceQuality(const MeshBuilder& mesh);
  std::vector<std::int32_t> wallChain(int vertex, std::map<int, std::vector<std::int32_t>>& chains, int rows,
                                      MeshBuilder& mesh) const;
  void addWallStrip(const std::vector<std::int32_t>& from, const std::vector<std::int32_t>& to, MeshBuilder& mesh,
                    std::size_t& counter) const;
};

SlabOverlay::SlabOverlay(const PreparedSlice* lower, const PreparedSlice* upper, double z0, double z1,
                         double tolerance)
  : m_Impl(std::make_unique<Impl>())
{
  Impl& d = *m_Impl;
  d.lower = lower && !lower->contours.empty() ? lower : nullptr;
  d.upper = upper && !upper->contours.empty() ? upper : nullptr;
  d.z0 = z0;
  d.z1 = z1;
  d.tolerance = tolerance;
  d.lowerContinues.assign(d.lower ? d.lower->contours.size() : 0, 0);
  d.upperContinues.assign(d.upper ? d.upper->contours.size() : 0, 0);
  if (!d.lower && !d.upper)
    return; // nothing to tile between two empty slices
  d.buildVertices();
  d.buildEdges();
  d.triangulate();
  d.classify();
}

SlabOverlay::~SlabOverlay() = default;

const std::vector<char>& SlabOverlay::lowerContinues() const
{
  return m_Impl->lowerContinues;
}

const std::vector<char>& SlabOverlay::upperContinues() const
{
  return m_Impl->upperContinues;
}

const std::vector<std::pair<int, int>>& SlabOverlay::correspondences() const
{
  return m_Impl->correspondences;
}

void SlabOverlay::Impl::buildVertices()
{
  // Points of the two slices closer than the tolerance are one overlay vertex: hash them on a grid
  // of the tolerance's size and look in the neighbouring cells.
  const double cell = std::max(tolerance, 1e-12);
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  auto key = [](long long x, long long y) {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
  };
  auto findNear = [&](const Point2& p) -> int {
    const long long cx = static_cast<long long>(std::floor(p.x / cell));
    const long long cy = static_cast<long long>(std::floor(p.y / cell));
    for (long long x = cx - 1; x <= cx + 1; ++x)
      for (long long y = cy - 1; y <= cy + 1; ++y)
      {
        auto it = grid.find(key(x, y));
        if (it == grid.end())
          continue;
        for (int index : it->second)
          if (distance(vertices[index].p, p) <= tolerance)
            return index;
      }
    return -1;
  };
  auto add = [&](const PreparedSlice* slice, bool isLower) {
    if (!slice)
      return;
    for (std::size_t c = 0; c < slice->contours.size(); ++c)
    {
      const Polygon2& polygon = slice->contours[c];
      for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const std::int32_t id = slice->firstVertexId[c] + static_cast<std::int32_t>(i);
        int index = findNear(polygon[i]);
        if (index >= 0 && (isLower ? vertices[index].lowerId : vertices[index].upperId) >= 0)
        {
          std::ostringstream message;
          message << "contours of the slice at z = " << slice->z << " mm touch each other at (" << polygon[i].x
                  << ", " << polygon[i].y << ")";
          throw Error(message.str());
        }
        if (index < 0)
        {
          index = static_cast<int>(vertices.size());
          vertices.push_back({ polygon[i] });
          grid[key(static_cast<long long>(std::floor(polygon[i].x / cell)),
                   static_cast<long long>(std::floor(polygon[i].y / cell)))]
            .push_back(index);
        }
        (isLower ? vertices[index].lowerId : vertices[index].upperId) = id;
      }
    }
  };
  add(lower, true);
  add(upper, false);
}

void SlabOverlay::Impl::buildEdges()
{
  // Overlay index of each contour vertex, by mesh id.
  std::unordered_map<std::int32_t, int> lowerIndex, upperIndex;
  for (int i = 0; i < static_cast<int>(vertices.size()); ++i)
  {
    if (vertices[i].lowerId >= 0)
      lowerIndex[vertices[i].lowerId] = i;
    if (vertices[i].upperId >= 0)
      upperIndex[vertices[i].upperId] = i;
  }
  auto add = [&](const PreparedSlice* slice, bool isLower, std::unordered_map<std::int32_t, int>& index,
                 std::vector<std::pair<Point2, Point2>>& segments) {
    if (!slice)
      return;
    for (std::size_t c = 0; c < slice->contours.size(); ++c)
    {
      const std::size_t n = slice->contours[c].size();
      for (std::size_t i = 0; i < n; ++i)
      {
        const int a = index.at(slice->firstVertexId[c] + static_cast<std::int32_t>(i));
        const int b = index.at(slice->firstVertexId[c] + static_cast<std::int32_t>((i + 1) % n));
        OverlayEdge& e = edges[edgeKey(a, b)];
        (isLower ? e.lower : e.upper) = true;
        (isLower ? e.lowerFrom : e.upperFrom) = a;
        (isLower ? e.lowerContour : e.upperContour) = static_cast<int>(c);
        segments.emplace_back(slice->contours[c][i], slice->contours[c][(i + 1) % n]);
      }
    }
  };
  add(lower, true, lowerIndex, lowerSegments);
  add(upper, false, upperIndex, upperSegments);
  double total = 0.0;
  for (const auto* set : { &lowerSegments, &upperSegments })
    for (const auto& [a, b] : *set)
      total += distance(a, b);
  const std::size_t count = lowerSegments.size() + upperSegments.size();
  typicalEdge = count > 0 ? std::max(total / count, 1e-6) : 1.0;
  lowerNearest = std::make_unique<NearestSegment>(lowerSegments, 2.0 * typicalEdge);
  upperNearest = std::make_unique<NearestSegment>(upperSegments, 2.0 * typicalEdge);
}

void SlabOverlay::Impl::triangulate()
{
  std::vector<std::pair<Kernel::Point_2, int>> points;
  points.reserve(vertices.size());
  for (int i = 0; i < static_cast<int>(vertices.size()); ++i)
    points.emplace_back(Kernel::Point_2(vertices[i].p.x, vertices[i].p.y), i);
  cdt.insert(points.begin(), points.end());
  if (cdt.number_of_vertices() != vertices.size())
    throw Error("slab overlay: two contour points coincide in projection beyond the merge tolerance");
  std::vector<VertexHandle> handles(vertices.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    handles[v->info()] = v;
  for (const auto& [key, edge] : edges)
  {
    (void)edge;
    cdt.insert_constraint(handles[key >> 32], handles[key & 0xffffffffULL]);
  }
  bool consistent = cdt.number_of_vertices() == vertices.size();
  Point2 where;
  for (auto e = cdt.finite_edges_begin(); consistent && e != cdt.finite_edges_end(); ++e)
    if (e->first->is_constrained(e->second) &&
        !edgeBetween(e->first->vertex(CDT::cw(e->second)), e->first->vertex(CDT::ccw(e->second))))
    {
      consistent = false;
      const auto& p = e->first->vertex(CDT::cw(e->second))->point();
      where = { p.x(), p.y() };
    }
  if (!consistent)
  {
    std::ostringstream message;
    message << "contours of the slices at z = " << z0 << " and " << z1
            << " mm cross or overlap where they should only meet at common vertices, near (" << where.x << ", "
            << where.y << ")";
    throw Error(message.str());
  }
}

void SlabOverlay::Impl::classify()
{
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info() = FaceData{};
  auto lowerParent = [&](int c) { return lower->nesting.parent[c]; };
  auto upperParent = [&](int c) { return upper->nesting.parent[c]; };

  // Flood fill from the outside: crossing a contour edge toggles membership of that slice's region
  // and steps in or out of that contour.
  std::deque<FaceHandle> queue;
  FaceHandle start = cdt.infinite_face();
  start->info().visited = true;
  queue.push_back(start);
  while (!queue.empty())
  {
    FaceHandle f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i)
    {
      FaceHandle g = f->neighbor(i);
      if (g->info().visited)
        continue;
      FaceData next = f->info();
      next.component = -1;
      if (f->is_constrained(i))
      {
        const OverlayEdge* e = edgeBetween(f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i)));
        if (!e)
          throw Error("slab overlay: a triangulation edge is not an edge of either slice");
        if (e->lower)
        {
          next.inLower = !next.inLower;
          next.lowerInnermost =
            next.lowerInnermost == e->lowerContour ? lowerParent(e->lowerContour) : e->lowerContour;
        }
        if (e->upper)
        {
          next.inUpper = !next.inUpper;
          next.upperInnermost =
            next.upperInnermost == e->upperContour ? upperParent(e->upperContour) : e->upperContour;
        }
      }
      next.visited = true;
      g->info() = next;
      queue.push_back(g);
    }
  }

  // Correspondence: a contour continues into the other slice where a face inside (for an outer
  // boundary) or inside its hole (for a hole) has the same status in the other slice.
  std::fill(lowerContinues.begin(), lowerContinues.end(), 0);
  std::fill(upperContinues.begin(), upperContinues.end(), 0);
  std::map<std::pair<int, int>, bool> pairs;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    const FaceData& info = f->info();
    if (info.inLower == info.inUpper)
    {
      if (info.lowerInnermost >= 0)
        lowerContinues[info.lowerInnermost] = 1;
      if (info.upperInnermost >= 0)
        upperContinues[info.upperInnermost] = 1;
      if (info.inLower)
        pairs[{ info.lowerInnermost, info.upperInnermost }] = true;
    }
  }
  correspondences.clear();
  for (const auto& entry : pairs)
    correspondences.push_back(entry.first);

  // Difference polygons: connected pieces of the symmetric difference, split by contour edges.
  components.clear();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info().inLower == f->info().inUpper || f->info().component >= 0)
      continue;
    const int id = static_cast<int>(components.size());
    Component component;
    component.lowerSide = f->info().inLower;
    std::vector<FaceHandle> stack{ f };
    f->info().component = id;
    while (!stack.empty())
    {
      FaceHandle g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i)
      {
        if (g->is_constrained(i))
        {
          const OverlayEdge* e = edgeBetween(g->vertex(CDT::cw(i)), g->vertex(CDT::ccw(i)));
          (edgeLevel(*e, component.lowerSide) == LowerLevel ? component.touchesLowerLevel
                                                             : component.touchesUpperLevel) = true;
          continue;
        }
        FaceHandle h = g->neighbor(i);
        if (!cdt.is_infinite(h) && h->info().component < 0)
        {
          h->info().component = id;
          stack.push_back(h);
        }
      }
    }
    components.push_back(component);
  }
  computeCapHeights();
}

std::vector<Sector> SlabOverlay::Impl::sectorsAround(VertexHandle v)
{
  // Faces around v counter-clockwise; the edge after face f (v at index i) is (f, ccw(i)).
  std::vector<FaceHandle> ring;
  auto circulator = cdt.incident_faces(v), done = circulator;
  do
  {
    ring.push_back(circulator);
  } while (++circulator != done);
  const std::size_t n = ring.size();
  std::size_t first = n;
  for (std::size_t k = 0; k < n; ++k)
    if (ring[k]->is_constrained(CDT::ccw(ring[k]->index(v))))
    {
      first = k;
      break;
    }
  std::vector<Sector> sectors;
  if (first == n)
    return sectors;
  // Walk once around, starting just after a contour edge.
  Sector current;
  current.vertex = v;
  for (std::size_t step = 1; step <= n; ++step)
  {
    FaceHandle f = ring[(first + step) % n];
    const int i = f->index(v);
    current.faces.push_back(f);
    if (f->is_constrained(CDT::ccw(i)))
    {
      sectors.push_back(current);
      current = Sector{};
      current.vertex = v;
    }
    else
      current.fan.push_back(f->vertex(CDT::cw(i)));
  }
  for (Sector& s : sectors)
  {
    FaceHandle f0 = s.faces.front(), f1 = s.faces.back();
    if (!isDifference(f0))
      continue;
    const bool lowerSide = components[f0->info().component].lowerSide;
    const int i0 = f0->index(v), i1 = f1->index(v);
    // The contour edge before the first face is (v, f0->vertex(ccw(i0))), after the last (v, f1->vertex(cw(i1))).
    s.startLevel = edgeLevel(*edgeBetween(v, f0->vertex(CDT::ccw(i0))), lowerSide);
    s.endLevel = edgeLevel(*edgeBetween(v, f1->vertex(CDT::cw(i1))), lowerSide);
  }
  return sectors;
}

double SlabOverlay::Impl::interpolatedHeight(const Point2& p) const
{
  // Distance-ratio interpolation between the two contours (the linear blend of their distance
  // transforms): 0 on the lower contour, 1 on the upper one.
  const double dLower = lowerNearest->distance(p);
  const double dUpper = upperNearest->distance(p);
  // Kept strictly inside the slab: a point lifted exactly onto a slice plane (a Steiner point a
  // rounding error away from a contour) could lie flat against the neighbouring slab's triangles.
  const double t = dLower + dUpper > 0.0 ? dLower / (dLower + dUpper) : 0.5;
  return z0 + std::clamp(t, 1e-3, 1.0 - 1e-3) * (z1 - z0);
}

std::vector<Sector> SlabOverlay::Impl::mixedSectors(bool assignCornerLevels)
{
  std::vector<Sector> mixed;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    if (!vertices[v->info()].onBoth())
      continue;
    for (Sector& s : sectorsAround(v))
    {
      if (!inMixed(s.faces.front()))
        continue;
      if (s.startLevel != s.endLevel)
        mixed.push_back(s);
      else if (assignCornerLevels)
        for (FaceHandle f : s.faces)
          f->info().cornerLevel[f->index(v)] = s.startLevel;
    }
  }
  return mixed;
}

std::size_t SlabOverlay::Impl::liftFlatChords(MeshBuilder& mesh)
{
  // A chord of a difference polygon whose two ends lie on the same slice would be flat on that
  // slice's plane, where the neighbouring slab may lay its own triangles (GEOMETRY_NOTES, trap 3).
  // Split such chords by Steiner points at interpolated heights until none is left; do the same
  // for the fan edges where the surface must switch between the two slices at a common vertex,
  // so that switch always happens towards a Steiner point.
  std::size_t inserted = 0;
  for (int round = 0; round < 64; ++round)
  {
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      f->info().cornerLevel = { NoLevel, NoLevel, NoLevel };
    std::vector<Point2> splits;
    for (const Sector& s : mixedSectors(true))
    {
      if (s.fan.empty())
      {
        FaceHandle f = s.faces.front();
        Point2 c{ 0.0, 0.0 };
        for (int i = 0; i < 3; ++i)
        {
          c.x += f->vertex(i)->point().x() / 3.0;
          c.y += f->vertex(i)->point().y() / 3.0;
        }
        splits.push_back(c);
        continue;
      }
      for (VertexHandle w : s.fan)
        if (!vertices[w->info()].isSteiner())
          splits.push_back({ 0.5 * (s.vertex->point().x() + w->point().x()),
                             0.5 * (s.vertex->point().y() + w->point().y()) });
    }
    for (const CDT::Edge& e : finiteEdgesInStableOrder(cdt))
    {
      FaceHandle f = e.first;
      const int i = e.second;
      if (f->is_constrained(i))
        continue;
      if (!needsLiftedChords(f))
        f = f->neighbor(i);
      if (cdt.is_infinite(f) || !needsLiftedChords(f))
        continue;
      // The edge's two ends, with their levels in face f (both faces of a chord agree on them).
      VertexHandle a = e.first->vertex(CDT::cw(i)), b = e.first->vertex(CDT::ccw(i));
      auto levelIn = [&](VertexHandle v) -> Level {
        const OverlayVertex& ov = vertices[v->info()];
        if (ov.isSteiner())
          return NoLevel;
        if (isCapFace(f))
          return components[f->info().component].capLevel();
        if (!ov.onBoth())
          return singleLevel(ov);
        return static_cast<Level>(f->info().cornerLevel[f->index(v)]);
      };
      const Level la = levelIn(a), lb = levelIn(b);
      if (la != NoLevel && la == lb)
        splits.push_back({ 0.5 * (a->point().x() + b->point().x()), 0.5 * (a->point().y() + b->point().y()) });
    }
    if (splits.empty())
      return inserted;
    std::sort(splits.begin(), splits.end(),
              [](const Point2& p, const Point2& q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); });
    for (std::size_t s = 0; s < splits.size(); ++s)
    {
      if (s > 0 && splits[s].x == splits[s - 1].x && splits[s].y == splits[s - 1].y)
        continue;
      const Point2& p = splits[s];
      CDT::Locate_type type;
      int index = 0;
      FaceHandle f = cdt.locate(Kernel::Point_2(p.x, p.y), type, index);
      if (type != CDT::VERTEX && !cdt.is_infinite(f) && isDifference(f))
        inserted += insertSteiner(p, steinerHeight(f, p), mesh);
    }
    classify();
  }
  std::ostringstream message;
  message << "tiling between z = " << z0 << " and " << z1 << " mm did not settle";
  throw Error(message.str());
}

std::vector<std::int32_t> SlabOverlay::Impl::wallChain(int vertex, std::map<int, std::vector<std::int32_t>>& chains,
                                                       int rows, MeshBuilder& mesh) const
{
  // The vertical edge at a vertex common to both slices, cut into rows, bottom to top.
  auto it = chains.find(vertex);
  if (it != chains.end())
    return it->second;
  const OverlayVertex& v = vertices[vertex];
  std::vector<std::int32_t> chain{ v.lowerId };
  const Point3 bottom = mesh.point(v.lowerId);
  const Point3 top = mesh.point(v.upperId);
  for (int r = 1; r < rows; ++r)
  {
    const double t = static_cast<double>(r) / rows;
    chain.push_back(mesh.addPoint(bottom.x + t * (top.x - bottom.x), bottom.y + t * (top.y - bottom.y),
                                  bottom.z + t * (top.z - bottom.z)));
  }
  chain.push_back(v.upperId);
  chains[vertex] = chain;
  return chain;
}

void SlabOverlay::Impl::addWallStrip(const std::vector<std::int32_t>& from, const std::vector<std::int32_t>& to,
                                     MeshBuilder& mesh, std::size_t& counter) const
{
  // A vertical strip along a contour edge from -> to (solid on the left), both chains bottom to top:
  // its triangles face away from the solid.
  for (std::size_t r = 0; r + 1 < from.size(); ++r)
  {
    mesh.addTriangle(from[r], to[r], to[r + 1]);
    mesh.addTriangle(from[r], to[r + 1], from[r + 1]);
    counter += 2;
  }
}

void SlabOverlay::Impl::computeCapHeights()
{
  capZ.assign(components.size(), std::numeric_limits<double>::quiet_NaN());
  if (!liftOptions)
    return;
  // The height a cap's dome reaches: half a slice beyond the last contour by default; a contour that
  // meets neither neighbour gets that thickness even when caps sit on their slice.
  const double dz = z1 - z0;
  const double baseOffset = liftOptions->capPlacement == CapPlacement::HalfSliceBeyond ? 0.5 * dz : 0.0;
  std::vector<char> needsThickness(components.size(), 0);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!isCapFace(f))
      continue;
    const Component& c = components[f->info().component];
    for (int i = 0; i < 3; ++i)
    {
      if (!f->is_constrained(i))
        continue;
      const OverlayEdge* e = edgeBetween(f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i)));
      const std::vector<char>* isolated =
        c.capLevel() == LowerLevel ? liftOptions->lowerIsolated : liftOptions->upperIsolated;
      const int contour = c.capLevel() == LowerLevel ? e->lowerContour : e->upperContour;
      if (isolated && contour >= 0 && static_cast<std::size_t>(contour) < isolated->size() && (*isolated)[contour])
        needsThickness[f->info().component] = 1;
    }
  }
  for (std::size_t c = 0; c < components.size(); ++c)
  {
    if (!components[c].isCap())
      continue;
    const double offset = needsThickness[c] ? 0.5 * dz : baseOffset;
    capZ[c] = components[c].capLevel() == LowerLevel ? z0 + offset : z1 - offset;
  }
}

Point3 SlabOverlay::Impl::approximateLift(FaceHandle f, int i, const MeshBuilder& mesh) const
{
  const OverlayVertex& v = vertices[f->vertex(i)->info()];
  if (v.isSteiner())
    return mesh.point(v.steinerId);
  if (isCapFace(f))
    return { v.p.x, v.p.y, capLevelZ(f->info().component) };
  if (v.onBoth())
  {
    const signed char level = f->info().cornerLevel[i];
    return { v.p.x, v.p.y, level == LowerLevel ? z0 : level == UpperLevel ? z1 : 0.5 * (z0 + z1) };
  }
  return { v.p.x, v.p.y, v.lowerId >= 0 ? z0 : z1 };
}

bool SlabOverlay::Impl::insertSteiner(const Point2& p, double z, MeshBuilder& mesh, double clearance)
{
  // Measured in 3D: a row point just above a contour in projection is fine, a point beside a contour
  // at that contour's own height makes a sliver.
  if (clearance > 0.0 && (std::hypot(lowerNearest->distance(p), z - z0) < clearance ||
                          std::hypot(upperNearest->distance(p), z1 - z) < clearance))
    return false;
  // Steiner points go strictly inside difference polygons: never on a contour edge, which the
  // neighbouring slab shares.
  CDT::Locate_type type;
  int index = 0;
  const Kernel::Point_2 point(p.x, p.y);
  FaceHandle f = cdt.locate(point, type, index);
  if (type == CDT::VERTEX || type == CDT::OUTSIDE_CONVEX_HULL || type == CDT::OUTSIDE_AFFINE_HULL)
    return false;
  if (type == CDT::EDGE && f->is_constrained(index))
    return false;
  if (!isDifference(f))
    return false;
  // A point a hair's breadth off a contour edge of its face (rows along a line that continues a
  // contour edge put points there up to rounding) makes a triangle of no width in projection that
  // no flip can remove: lifted, it stands vertical and its neighbour folds onto it, a fold that
  // rounding then turns into crossing triangles (seen after an oblique direction was applied).
  // Optional points only: a chord's midpoint is needed, and chords are not contour edges.
  if (clearance > 0.0 && type == CDT::FACE)
    for (int i = 0; i < 3; ++i)
    {
      if (!f->is_constrained(i))
        continue; // a sliver against an ordinary edge is flipped away by the Delaunay insertion
      const auto& a = f->vertex(CDT::cw(i))->point();
      const auto& b = f->vertex(CDT::ccw(i))->point();
      if (distanceToSegment(p, { a.x(), a.y() }, { b.x(), b.y() }) < 1e-3 * typicalEdge)
        return false;
    }
  // The new faces lie in the same difference polygon (insertion never crosses a constraint): they
  // inherit its classification, so further insertions can be placed before the next classify().
  FaceData region = f->info();
  region.cornerLevel = { NoLevel, NoLevel, NoLevel };
  region.lifted = { -1, -1, -1 };
  VertexHandle v = cdt.insert(point, type, f, index);
  auto face = cdt.incident_faces(v), done = face;
  do
    face->info() = region;
  while (++face != done);
  OverlayVertex steiner;
  steiner.p = p;
  steiner.steinerId = mesh.addPoint(p.x, p.y, z);
  v->info() = static_cast<int>(vertices.size());
  vertices.push_back(steiner);
  return true;
}

namespace
{

/** Points already placed, to keep new Steiner points a minimum 3D distance apart. */
class SpacingGrid
{
public:
  explicit SpacingGrid(double cell)
    : m_Cell(std::max(cell, 1e-9))
  {
  }
  void add(const Point3& p) { m_Cells[key(cellOf(p.x), cellOf(p.y))].push_back(p); }
  bool hasPointWithin(const Point3& p, double radius) const
  {
    const long long reach = static_cast<long long>(std::ceil(radius / m_Cell));
    const long long cx = cellOf(p.x), cy = cellOf(p.y);
    for (long long x = cx - reach; x <= cx + reach; ++x)
      for (long long y = cy - reach; y <= cy + reach; ++y)
      {
        auto it = m_Cells.find(key(x, y));
        if (it == m_Cells.end())
          continue;
        for (const Point3& q : it->second)
          if (std::hypot(p.x - q.x, p.y - q.y, p.z - q.z) < radius)
            return true;
      }
    return false;
  }

private:
  long long cellOf(double v) const { return static_cast<long long>(std::floor(v / m_Cell)); }
  static std::uint64_t key(long long x, long long y)
  {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
  }
  double m_Cell;
  std::unordered_map<std::uint64_t, std::vector<Point3>> m_Cells;
};

Point3 circumcenter(const Point3& a, const Point3& b, const Point3& c)
{
  // a + ((|u|^2 v - |v|^2 u) x (u x v)) / (2 |u x v|^2), u = b - a, v = c - a.
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double n2 = nx * nx + ny * ny + nz * nz;
  const double u2 = ux * ux + uy * uy + uz * uz, v2 = vx * vx + vy * vy + vz * vz;
  const double wx = u2 * vx - v2 * ux, wy = u2 * vy - v2 * uy, wz = u2 * vz - v2 * uz;
  return { a.x + (wy * nz - wz * ny) / (2 * n2), a.y + (wz * nx - wx * nz) / (2 * n2),
           a.z + (wx * ny - wy * nx) / (2 * n2) };
}

} // namespace

double SlabOverlay::Impl::domeHeight(int component, const Point2& p) const
{
  // A cap is a dome over its contour: it leaves the contour's slice and, within a distance equal to
  // its height, reaches the cap height (half a slice beyond by default) on a quarter-circle profile,
  // the rounded end a smooth structure has and the voxels' extent in the middle.
  const double base = capLevelZ(component);
  const double rise = capZ[component] - base;
  if (rise == 0.0)
    return base;
  const NearestSegment& rim = components[component].capLevel() == LowerLevel ? *lowerNearest : *upperNearest;
  const double s = std::min(1.0, rim.distance(p) / std::abs(rise));
  // Never flat on the contour's own slice, where the neighbouring slab's triangles meet it.
  return base + rise * std::max(1e-3, std::sqrt(1.0 - (1.0 - s) * (1.0 - s)));
}

std::size_t SlabOverlay::Impl::addCapRows(MeshBuilder& mesh, double edgeLength)
{
  // Rows of Steiner points parallel to each domed cap's contour, an edge length apart in 3D, so the
  // dome's rounded rim is tiled by well-shaped triangles; the flat top is filled by refinement.
  SpacingGrid placed(edgeLength);
  addLiftedCorners(placed, mesh);
  std::vector<std::pair<Point2, double>> candidates;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    if (vertices[v->info()].isSteiner())
      continue;
    // Inwards: towards the centroid of the vertex's cap faces.
    Point2 towards{ 0.0, 0.0 };
    int component = -1, count = 0;
    auto face = cdt.incident_faces(v), done = face;
    do
    {
      if (!cdt.is_infinite(face) && isCapFace(face) && needsLiftedChords(face))
      {
        component = face->info().component;
        for (int i = 0; i < 3; ++i)
        {
          towards.x += face->vertex(i)->point().x() / 3.0;
          towards.y += face->vertex(i)->point().y() / 3.0;
        }
        ++count;
      }
    } while (++face != done);
    if (count == 0)
      continue;
    const Point2 origin{ v->point().x(), v->point().y() };
    double dx = towards.x / count - origin.x, dy = towards.y / count - origin.y;
    const double length = std::hypot(dx, dy);
    if (length == 0.0)
      continue;
    dx /= length;
    dy /= length;
    const double rise = std::abs(capZ[component] - capLevelZ(component));
    // Along the quarter circle of radius `rise`, rows an edge length apart in arc length.
    const int rows = static_cast<int>(std::ceil(0.5 * M_PI * rise / edgeLength));
    for (int r = 1; r <= rows; ++r)
    {
      const double angle = 0.5 * M_PI * r / rows;
      const double inward = rise * (1.0 - std::cos(angle));
      const Point2 p{ origin.x + dx * inward, origin.y + dy * inward };
      CDT::Locate_type type;
      int index = 0;
      FaceHandle f = cdt.locate(Kernel::Point_2(p.x, p.y), type, index);
      if (type == CDT::VERTEX || cdt.is_infinite(f) || !isCapFace(f) || f->info().component != component)
        continue;
      const double z = domeHeight(component, p);
      if (placed.hasPointWithin({ p.x, p.y, z }, 0.6 * edgeLength))
        continue;
      placed.add({ p.x, p.y, z });
      candidates.emplace_back(p, z);
    }
  }
  return insertCandidates(candidates, mesh, [&](FaceHandle f) { return isCapFace(f); });
}

std::size_t SlabOverlay::Impl::addRows(MeshBuilder& mesh, double edgeLength)
{
  // Between a contour and the other slice's contour the surface climbs the slab; rows of Steiner
  // points at the spacing of the edge length let its triangles be about as tall as they are wide
  // in 3D (a 1 mm contour spacing under 3 mm slices would otherwise give slivers only).
  const double dz = z1 - z0;
  SpacingGrid placed(edgeLength);
  addLiftedCorners(placed, mesh);
  // Columns start from the contour vertices of one slice only, the one with more of them, so the
  // rows line up: the planar Delaunay triangulation of aligned rows is well shaped in 3D even where
  // the slope compresses the rows in projection; staggered rows from both sides are not.
  std::vector<VertexHandle> starts[2];
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    const Level level = singleLevel(vertices[v->info()]);
    if (level == NoLevel)
      continue;
    bool onMixed = false;
    auto face = cdt.incident_faces(v), done = face;
    do
      onMixed = onMixed || inMixed(face);
    while (++face != done && !onMixed);
    if (onMixed)
      starts[level].push_back(v);
  }
  const Level level = starts[LowerLevel].size() >= starts[UpperLevel].size() ? LowerLevel : UpperLevel;
  std::vector<std::pair<Point2, double>> candidates;
  for (VertexHandle v : starts[level])
  {
    const OverlayVertex& ov = vertices[v->info()];
    Point2 target;
    const double flat = (level == LowerLevel ? upperNearest : lowerNearest)->nearest(ov.p, &target);
    int m = static_cast<int>(std::lround(std::hypot(flat, dz) / edgeLength));
    // Rows closer than a few percent of the edge length in projection cannot be told apart by
    // the planar triangulation.
    m = std::min(m, static_cast<int>(std::floor(flat / (0.05 * edgeLength))));
    for (int r = 1; r < m; ++r)
    {
      const double t = static_cast<double>(r) / m;
      const Point2 p{ ov.p.x + t * (target.x - ov.p.x), ov.p.y + t * (target.y - ov.p.y) };
      const double z = interpolatedHeight(p);
      if (placed.hasPointWithin({ p.x, p.y, z }, 0.6 * edgeLength))
        continue;
      placed.add({ p.x, p.y, z });
      candidates.emplace_back(p, z);
    }
  }
  return insertCandidates(candidates, mesh, [&](FaceHandle f) { return inMixed(f); });
}

void SlabOverlay::Impl::addLiftedCorners(SpacingGrid& placed, const MeshBuilder& mesh) const
{
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (isDifference(f))
      for (int i = 0; i < 3; ++i)
        placed.add(approximateLift(f, i, mesh));
}

std::size_t SlabOverlay::Impl::insertCandidates(const std::vector<std::pair<Point2, double>>& candidates,
                                                MeshBuilder& mesh, const std::function<bool(FaceHandle)>& accepts)
{
  std::size_t inserted = 0;
  for (const auto& [p, z] : candidates)
  {
    CDT::Locate_type type;
    int index = 0;
    FaceHandle f = cdt.locate(Kernel::Point_2(p.x, p.y), type, index);
    if (type != CDT::VERTEX && !cdt.is_infinite(f) && accepts(f))
      inserted += insertSteiner(p, z, mesh, optionalClearance());
  }
  if (inserted > 0)
    classify();
  return inserted;
}

std::size_t SlabOverlay::Impl::refineBadTriangles(MeshBuilder& mesh, double minAngle, double edgeLength,
                                                  std::size_t budget)
{
  // Delaunay refinement judged on the lifted triangles: a triangle whose smallest 3D angle is under
  // the target gets the projection of its 3D circumcentre, lifted by the interpolant. Points go
  // only inside difference polygons (contour edges are shared with the next slab and stay whole),
  // so triangles held by short contour edges may stay bad; the budget bounds the work.
  std::size_t inserted = 0;
  for (int round = 0; round < 12 && inserted < budget; ++round)
  {
    SpacingGrid placed(edgeLength);
    std::vector<std::pair<Point2, double>> candidates; // point, the bad triangle's circumradius
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
      if (!isDifference(f))
        continue;
      const Point3 a = approximateLift(f, 0, mesh), b = approximateLift(f, 1, mesh), c = approximateLift(f, 2, mesh);
      placed.add(a);
      placed.add(b);
      placed.add(c);
      if (minAngle3(a, b, c) >= minAngle)
        continue;
      const Point3 center = circumcenter(a, b, c);
      const double radius = std::hypot(center.x - a.x, center.y - a.y, center.z - a.z);
      if (!std::isfinite(radius) || radius < 0.3 * edgeLength)
        continue;
      candidates.push_back({ { center.x, center.y }, radius });
    }
    std::size_t added = 0;
    for (const auto& [p, radius] : candidates)
    {
      CDT::Locate_type type;
      int index = 0;
      FaceHandle f = cdt.locate(Kernel::Point_2(p.x, p.y), type, index);
      if (type == CDT::VERTEX || cdt.is_infinite(f) || !isDifference(f))
        continue;
      const double z = steinerHeight(f, p);
      if (placed.hasPointWithin({ p.x, p.y, z }, 0.5 * radius))
        continue;
      if (insertSteiner(p, z, mesh, optionalClearance()))
      {
        placed.add({ p.x, p.y, z });
        ++added;
      }
    }
    if (added == 0)
      break;
    inserted += added;
    classify();
    // Insertion restores planar Delaunay around each new point; restore the surface metric too.
    if (liftOptions && liftOptions->surfaceMetricFlips)
      flipTowardsSurfaceQuality(mesh);
  }
  return inserted;
}

std::size_t SlabOverlay::Impl::flipTowardsSurfaceQuality(const MeshBuilder& mesh)
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
    const double before = std::min(minAngle3(A, P, Q), minAngle3(B, Q, P));
    const double after = std::min(minAngle3(A, B, Q), minAngle3(B, A, P));
    // Nor into a crease sharper than a right angle across the new edge: steep triangles have good
    // angles, but two of them meeting in a knife-edge ridge nearly fold onto each other.
    const double crease = normalsCosine(A, B, Q, P);
    if (crease < 0.0 && crease < normalsCosine(P, Q, A, B))
      return false;
    return after > before + 1e-9;
  };
  // The worst triangles' edges are taken first (the queue pops from the back): the flips then settle
  // in a better local optimum than in mesh order.
  std::vector<std::pair<double, CDT::Edge>> ranked;
  for (const CDT::Edge& e : finiteEdgesInStableOrder(cdt))
    if (!e.first->is_constrained(e.second) && isDifference(e.first) && !cdt.is_infinite(e.first->neighbor(e.second)))
    {
      const FaceHandle f = e.first, g = f->neighbor(e.second);
      const double worst = std::min(minAngle3(lifted(f->vertex(0)), lifted(f->vertex(1)), lifted(f->vertex(2))),
                                    minAngle3(lifted(g->vertex(0)), lifted(g->vertex(1)), lifted(g->vertex(2))));
      ranked.emplace_back(worst, e);
    }
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
    for (VertexHandle w : { u, v })
    {
      queue.emplace_back(a, w);
      queue.emplace_back(b, w);
    }
  }
  return flips;
}

void SlabOverlay::lift(MeshBuilder& mesh, const SlabLiftOptions& options, ReconstructionStatistics& statistics)
{
  Impl& d = *m_Impl;
  if (d.vertices.empty())
    return;
  d.liftOptions = &options;
  d.computeCapHeights();
  const double dz = d.z1 - d.z0;
  const int rows = std::max(1, static_cast<int>(std::lround(dz / options.rowHeight)));

  // Rows first: the flat-chord splits then fall on the few chords the rows leave.
  if (options.minAngleDegrees > 0.0)
  {
    const double edgeLength = options.maxEdgeLength > 0.0 ? options.maxEdgeLength : options.rowHeight;
    statistics.steinerPoints += d.addRows(mesh, edgeLength);
    statistics.steinerPoints += d.addCapRows(mesh, edgeLength);
    statistics.steinerPoints += d.liftFlatChords(mesh);
    const std::size_t budget = 20 * d.vertices.size() + 100;
    if (options.surfaceMetricFlips)
      d.flipTowardsSurfaceQuality(mesh);
    statistics.steinerPoints += d.refineBadTriangles(mesh, options.minAngleDegrees * M_PI / 180.0, edgeLength, budget);
  }
  statistics.steinerPoints += d.liftFlatChords(mesh);
  if (options.minAngleDegrees > 0.0 && options.surfaceMetricFlips)
    d.flipTowardsSurfaceQuality(mesh);

  // Where the surface switches from one slice to the other at a vertex common to both, the rise is
  // spread over the sector's fan: each face takes the node of the vertex's vertical chain nearest the
  // height of its Steiner corners, and each fan edge where consecutive faces differ carries a small
  // vertical fan over the chain nodes between them (one tall fan from a single point would be slivers).
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
  {
    f->info().cornerLevel = { NoLevel, NoLevel, NoLevel };
    f->info().cornerId = { -1, -1, -1 };
  }
  struct Switch
  {
    std::int32_t far;                 ///< the fan edge's Steiner end
    FaceHandle before;                ///< the face on the start side of the fan edge
    std::vector<std::int32_t> nodes;  ///< chain nodes climbed, in the direction from start to end
  };
  std::map<int, std::vector<std::int32_t>> chains;
  std::vector<Switch> switches;
  for (const Sector& s : d.mixedSectors(true))
  {
    std::vector<std::int32_t> chain = d.wallChain(s.vertex->info(), chains, rows, mesh);
    if (s.startLevel == UpperLevel)
      std::reverse(chain.begin(), chain.end());
    const int n = static_cast<int>(chain.size()) - 1;
    const double zStart = mesh.point(chain.front()).z, zEnd = mesh.point(chain.back()).z;
    auto fraction = [&](VertexHandle w) {
      return std::clamp((mesh.point(d.vertices[w->info()].steinerId).z - zStart) / (zEnd - zStart), 0.0, 1.0);
    };
    const std::size_t faces = s.faces.size();
    std::vector<int> node(faces, 0);
    node.back() = n;
    for (std::size_t k = 1; k + 1 < faces; ++k)
      node[k] = std::clamp(static_cast<int>(std::lround(0.5 * (fraction(s.fan[k - 1]) + fraction(s.fan[k])) * n)),
                           node[k - 1], n);
    for (std::size_t k = 0; k < faces; ++k)
      s.faces[k]->info().cornerId[s.faces[k]->index(s.vertex)] = chain[node[k]];
    for (std::size_t k = 0; k + 1 < faces; ++k)
      if (node[k] != node[k + 1])
        switches.push_back({ d.vertices[s.fan[k]->info()].steinerId, s.faces[k],
                             std::vector<std::int32_t>(chain.begin() + node[k], chain.begin() + node[k + 1] + 1) });
  }

  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
  {
    if (!d.isDifference(f))
      continue;
    const Component& c = d.components[f->info().component];
    std::array<std::int32_t, 3> ids;
    for (int i = 0; i < 3; ++i)
    {
      const OverlayVertex& v = d.vertices[f->vertex(i)->info()];
      if (v.isSteiner())
        ids[i] = v.steinerId;
      else if (c.isCap())
        ids[i] = c.capLevel() == LowerLevel ? v.lowerId : v.upperId;
      else if (!v.onBoth())
        ids[i] = v.lowerId >= 0 ? v.lowerId : v.upperId;
      else if (f->info().cornerId[i] >= 0)
        ids[i] = f->info().cornerId[i];
      else
      {
        const signed char level = f->info().cornerLevel[i];
        if (level == NoLevel)
          throw Error("tiling: a vertex common to both slices has no level (internal error)");
        ids[i] = level == LowerLevel ? v.lowerId : v.upperId;
      }
    }
    // Counter-clockwise seen from above faces up: right for lower \ upper (solid below).
    if (!c.lowerSide)
      std::swap(ids[1], ids[2]);
    f->info().lifted = ids;
    mesh.addTriangle(ids[0], ids[1], ids[2]);
    ++(c.isCap() ? statistics.capTriangles : statistics.tilingTriangles);
  }

  // The vertical fans, wound to match the face before them.
  for (const Switch& s : switches)
  {
    const auto& t = s.before->info().lifted;
    bool farToVertex = false; // whether the face before the switch runs far -> nodes[0]
    for (int i = 0; i < 3; ++i)
      if (t[i] == s.far && t[(i + 1) % 3] == s.nodes.front())
        farToVertex = true;
    for (std::size_t r = 0; r + 1 < s.nodes.size(); ++r)
    {
      if (farToVertex)
        mesh.addTriangle(s.nodes[r], s.far, s.nodes[r + 1]);
      else
        mesh.addTriangle(s.far, s.nodes[r], s.nodes[r + 1]);
      ++statistics.wallTriangles;
    }
  }

  // Walls where the two slices' contours coincide and run the same way.
  for (const auto& [key, e] : d.edges)
  {
    (void)key;
    if (!(e.lower && e.upper && e.lowerFrom == e.upperFrom))
      continue;
    const int from = e.lowerFrom;
    const int to = static_cast<int>(key >> 32) == from ? static_cast<int>(key & 0xffffffffULL)
                                                        : static_cast<int>(key >> 32);
    d.addWallStrip(d.wallChain(from, chains, rows, mesh), d.wallChain(to, chains, rows, mesh), mesh,
                   statistics.wallTriangles);
  }
}

} // namespace slicemesh

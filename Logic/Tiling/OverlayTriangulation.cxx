// Step 4 of Documentation/Algorithm.md, first half: the two slices of a slab overlaid in one
// constrained Delaunay triangulation, their common points merged and their contour edges constrained.
#include "Tiling/SlabOverlayState.h"

#include "Core/PlanarGeometry.h"
#include "Core/SpatialHash.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

namespace slicemesh
{

using namespace slab;

/** CGAL's edge iterator reports an edge from whichever of its two faces lies at the lower address, so
 *  its order (and the face an edge is seen from) would change from run to run with the heap's layout,
 *  and the flips, the Steiner points and the mesh with it. Here an edge is seen from the face in which
 *  it runs from the lower vertex id to the higher one (or from its only finite face). */
std::vector<CDT::Edge> slab::finiteEdgesInStableOrder(const CDT& cdt)
{
  std::vector<CDT::Edge> edges;
  edges.reserve(3 * cdt.number_of_faces());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i)
      if (cdt.is_infinite(f->neighbor(i)) || f->vertex(CDT::cw(i))->info() < f->vertex(CDT::ccw(i))->info())
        edges.emplace_back(f, i);
  return edges;
}

/** The side of the cells that locate's walks start from, in typical contour edges: a walk from a
 *  vertex of p's own cell crosses a few triangles. */
constexpr double vertexCellEdges = 4.0;

void SlabOverlay::Impl::addToVertexCells(VertexHandle v)
{
  if (!vertexCells)
    vertexCells = std::make_unique<SpatialHash>(vertexCellEdges * typicalEdge);
  const int id = v->info();
  if (vertexHandles.size() <= static_cast<std::size_t>(id))
    vertexHandles.resize(static_cast<std::size_t>(id) + 1);
  vertexHandles[static_cast<std::size_t>(id)] = v;
  vertexCells->insert(Point2{ v->point().x(), v->point().y() }, id);
}

FaceHandle SlabOverlay::Impl::locate(const Kernel::Point_2& p, CDT::Locate_type& type, int& index) const
{
  if (vertexCells)
  {
    const SpatialHash::Cell cell = vertexCells->cell(vertexCells->cellOf(p.x()), vertexCells->cellOf(p.y()));
    if (cell.begin() != cell.end())
      locateHint = vertexHandles[static_cast<std::size_t>(*cell.begin())];
  }
  FaceHandle f = cdt.locate(p, type, index, locateHint == VertexHandle() ? FaceHandle() : locateHint->face());
  if (type == CDT::EDGE && cdt.dimension() == 2) // below two dimensions an edge has no two faces
  {
    const FaceHandle g = f->neighbor(index);
    const bool gFirst = cdt.is_infinite(f) ||
                        (!cdt.is_infinite(g) && g->vertex(g->index(f))->info() < f->vertex(index)->info());
    if (gFirst)
    {
      index = g->index(f);
      f = g;
    }
  }
  for (int i = 0; i < 3; ++i)
    if (!cdt.is_infinite(f->vertex(i)))
    {
      locateHint = f->vertex(i);
      break;
    }
  return f;
}

namespace
{

/** The values, one per key, in key order: an order that depends on the vertex ids only, never on
 *  where the triangulation's faces lie in memory. Equal keys stand for one face or edge. */
template <typename Key, typename Value>
std::vector<Value> inKeyOrder(std::vector<std::pair<Key, Value>> keyed)
{
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  keyed.erase(std::unique(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
              keyed.end());
  std::vector<Value> values;
  values.reserve(keyed.size());
  for (auto& [key, value] : keyed)
    values.push_back(value);
  return values;
}

/** A face's three vertex ids in increasing order. */
std::array<int, 3> sortedIds(FaceHandle f)
{
  std::array<int, 3> ids{ f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info() };
  std::sort(ids.begin(), ids.end());
  return ids;
}

/** Sorted ids packed into one integer that orders as they do, 21 bits each; nullopt where an id
 *  does not fit (negative, or a slab of over two million points). Sorting these rather than arrays
 *  was most of the time of finiteFacesAround. */
std::optional<std::uint64_t> packedFaceKey(const std::array<int, 3>& ids)
{
  constexpr int bits = 21;
  if (ids[0] < 0 || ids[2] >= (1 << bits))
    return std::nullopt;
  return (static_cast<std::uint64_t>(ids[0]) << (2 * bits)) | (static_cast<std::uint64_t>(ids[1]) << bits) |
         static_cast<std::uint64_t>(ids[2]);
}

} // namespace

std::vector<CDT::Edge> slab::finiteEdgesAround(const CDT& cdt, const std::vector<VertexHandle>& around)
{
  // Keyed by their ends' ids; an edge between two finite faces is taken from the face where it runs
  // from the smaller id to the larger, as finiteEdgesInStableOrder takes it.
  std::vector<std::pair<std::uint64_t, CDT::Edge>> keyed;
  for (const FaceHandle f : finiteFacesAround(cdt, around))
    for (int i = 0; i < 3; ++i)
    {
      const int a = f->vertex(CDT::cw(i))->info(), b = f->vertex(CDT::ccw(i))->info();
      CDT::Edge edge(f, i);
      if (a > b && !cdt.is_infinite(f->neighbor(i)))
        edge = CDT::Edge(f->neighbor(i), cdt.mirror_index(f, i));
      // Both ids in one integer, ordered as the pair of ids is (sorting pairs took longer).
      keyed.push_back({ (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b)),
                        edge });
    }
  return inKeyOrder(std::move(keyed));
}

std::vector<FaceHandle> slab::finiteFacesAround(const CDT& cdt, const std::vector<VertexHandle>& around)
{
  std::vector<FaceHandle> faces;
  for (const VertexHandle v : around)
  {
    auto face = cdt.incident_faces(v), done = face;
    if (face == nullptr)
      continue;
    do
      if (!cdt.is_infinite(face))
        faces.push_back(face);
    while (++face != done);
  }
  std::vector<std::pair<std::uint64_t, FaceHandle>> packed;
  packed.reserve(faces.size());
  for (const FaceHandle f : faces)
    if (const std::optional<std::uint64_t> key = packedFaceKey(sortedIds(f)))
      packed.push_back({ *key, f });
  if (packed.size() == faces.size())
    return inKeyOrder(std::move(packed));
  std::vector<std::pair<std::array<int, 3>, FaceHandle>> keyed;
  for (const FaceHandle f : faces)
    keyed.push_back({ sortedIds(f), f });
  return inKeyOrder(std::move(keyed));
}

void SlabOverlay::Impl::buildVertices()
{
  // Points of the two slices closer than the tolerance are one overlay vertex: hash them on a grid
  // of the tolerance's size and look in the neighbouring cells.
  SpatialHash grid(std::max(tolerance, 1e-12));
  auto findNear = [&](const Point2& p) -> int {
    int found = -1;
    grid.anyIn(grid.cellsWithin(p, grid.cellSize()), [&](int index) {
      if (distance(vertices[index].p, p) > tolerance)
        return false;
      found = index;
      return true;
    });
    return found;
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
          grid.insert(polygon[i], index);
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
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    addToVertexCells(v); // vertexHandles by id, for the constraints and the locate
  for (const auto& [key, edge] : edges)
  {
    (void)edge;
    cdt.insert_constraint(vertexHandles[key >> 32], vertexHandles[key & 0xffffffffULL]);
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

} // namespace slicemesh

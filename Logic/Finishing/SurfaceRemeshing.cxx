#include "Finishing/SurfaceRemeshing.h"

#include "Core/AreaNormal.h"
#include "Core/ParallelFor.h"
#include "Finishing/HeldContourEdges.h"
#include "Finishing/RemeshingPasses.h"
#include "Finishing/RemeshingRegions.h"
#include "Measures/ClosestPointGrid.h"
#include "Measures/TriangleAngles.h"
#include "Measures/MeshComponents.h"
#include "Measures/SurfaceMeshConversion.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <chrono>
#include <cmath>
#include <deque>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace slicemesh
{
namespace
{

using Kernel = CgalKernel;
using SurfaceMesh = CgalSurfaceMesh;
using Vertex = SurfaceMesh::Vertex_index;
using InputGrid = ClosestPointGrid;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh surfaceOf(const TriangleMesh& mesh)
{
  SurfaceMesh surface;
  const std::size_t misfit = toSurfaceMesh(mesh, surface);
  if (misfit != mesh.triangles.size())
    throw Error("surface remeshing: triangle " + std::to_string(misfit) + " does not fit a manifold surface");
  return surface;
}

TriangleMesh toTriangleMesh(SurfaceMesh& surface)
{
  surface.collect_garbage();
  TriangleMesh mesh;
  mesh.points.reserve(surface.number_of_vertices());
  for (Vertex v : surface.vertices())
  {
    const Kernel::Point_3& p = surface.point(v);
    mesh.points.push_back({ p.x(), p.y(), p.z() });
  }
  mesh.triangles.reserve(surface.number_of_faces());
  for (SurfaceMesh::Face_index f : surface.faces())
  {
    Triangle triangle{};
    int corner = 0;
    for (Vertex v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      triangle[corner++] = static_cast<std::int32_t>(v.idx());
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

/** Whether the triangles around v are unfolded: every two consecutive ones with area face the same
 *  side (positive dot product of their normals), and at least one has area. */
bool unfoldedAround(Vertex v, const SurfaceMesh& surface)
{
  Kernel::Vector_3 first = CGAL::NULL_VECTOR, previous = CGAL::NULL_VECTOR;
  bool any = false;
  for (SurfaceMesh::Halfedge_index h : CGAL::halfedges_around_target(v, surface))
  {
    if (surface.is_border(h))
      continue;
    // Only the signs of dot products matter: the area normal, not the unit normal.
    const Kernel::Vector_3 n = areaNormal(surface, h);
    if (n == CGAL::NULL_VECTOR)
      continue; // no area, no direction
    if (!any)
      first = n;
    else if (n * previous <= 0.0)
      return false;
    previous = n;
    any = true;
  }
  // A vertex all of whose triangles lost their area cannot be judged: its move is refused. (This is
  // the case that makes CGAL 5.5's own relaxation step read a null halfedge, CGAL issue 7345.)
  return any && first * previous > 0.0;
}

/** One tangential relaxation sweep (Botsch and Kobbelt): every vertex goes towards the centroid of
 *  its neighbours, within its tangent plane. Targets are computed first, then applied one vertex
 *  at a time; a move that folds the triangles around its vertex is halved (five times at most) and
 *  otherwise dropped. This is the step isotropic_remeshing runs itself, done here because CGAL
 *  5.5's version dereferences a null halfedge when every triangle around a moved vertex is
 *  degenerate, which thresholded MRI reaches. With `only` (a flag per vertex index), only the
 *  vertices flagged move. */
void relaxTangentially(SurfaceMesh& surface, unsigned int threads, const std::vector<char>* only = nullptr)
{
  // Vertex indices are dense here (the caller collected the garbage); every vertex's normal and
  // target is its own, computed from the unmoved surface, so the ranges run side by side.
  const std::size_t vertexCount = surface.number_of_vertices();
  // Not a structured binding: the lambdas below capture it (C++17 does not allow that for bindings).
  auto faceNormals = surface.add_property_map<SurfaceMesh::Face_index, Kernel::Vector_3>("f:relaxation_normal").first;
  parallelForRanges(surface.number_of_faces(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t f = first; f < last; ++f)
                        faceNormals[SurfaceMesh::Face_index(f)] =
                          PMP::compute_face_normal(SurfaceMesh::Face_index(f), surface);
                    });
  std::vector<std::optional<Kernel::Point_3>> targets(vertexCount);
  parallelForRanges(vertexCount, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t index = first; index < last; ++index)
                      {
                        const Vertex v(static_cast<SurfaceMesh::size_type>(index));
                        if (surface.is_isolated(v) || surface.is_border(v) || (only && !(*only)[index]))
                          continue;
                        // The tangent plane: the mean of the unit normals around the vertex. (CGAL's
                        // compute_vertex_normal looks for the normal most visible from every face,
                        // which took a fifth of the remesh; a tangent plane needs no more than this.)
                        Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
                        for (SurfaceMesh::Face_index f : CGAL::faces_around_target(surface.halfedge(v), surface))
                          if (f != SurfaceMesh::null_face())
                            sum = sum + faceNormals[f];
                        const double length = std::sqrt(sum.squared_length());
                        if (!(length > 0.0))
                          continue; // no triangle around it has area: no plane to move in
                        const Kernel::Vector_3 n = sum / length;
                        const Kernel::Point_3& p = surface.point(v);
                        Kernel::Vector_3 toCentroid = CGAL::NULL_VECTOR;
                        int neighbours = 0;
                        for (Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface))
                        {
                          toCentroid = toCentroid + Kernel::Vector_3(p, surface.point(u));
                          ++neighbours;
                        }
                        const Kernel::Point_3 centroid = p + toCentroid / static_cast<double>(neighbours);
                        targets[index] = centroid + (n * Kernel::Vector_3(centroid, p)) * n;
                      }
                    });
  surface.remove_property_map(faceNormals);
  // Applied one vertex at a time, in order: each fold test sees the moves before it.
  for (std::size_t index = 0; index < vertexCount; ++index)
  {
    if (!targets[index])
      continue;
    const Vertex v(static_cast<SurfaceMesh::size_type>(index));
    const Kernel::Point_3 initial = surface.point(v);
    const Kernel::Vector_3 move(initial, *targets[index]);
    surface.point(v) = *targets[index];
    double fraction = 1.0;
    while (fraction > 0.03 && !unfoldedAround(v, surface))
    {
      fraction *= 0.5;
      surface.point(v) = initial + fraction * move;
    }
    if (fraction <= 0.02)
      surface.point(v) = initial;
  }
}

/** Where a remesh leaves a regular pattern of narrow triangles (rings of vertices half a slice apart
 *  around a thin tube along the slices), neither its split nor its collapse applies: the shortest
 *  edge of each triangle under 30 degrees is collapsed to its midpoint here, when the link condition
 *  holds, no edge around either end is constrained (the region's border and the edges beside it
 *  are), no triangle around it turns over and no edge grows past twice the target. Returns the
 *  vertex each collapse kept (a later collapse can have removed it). */
std::vector<Vertex> collapseNarrowEdges(SurfaceMesh& surface,
                                        const SurfaceMesh::Property_map<SurfaceMesh::Edge_index, bool>& constrained,
                                        double targetEdgeLength)
{
  const double cos30 = std::cos(M_PI / 6.0);
  auto at = [&](Vertex v) {
    const Kernel::Point_3& p = surface.point(v);
    return Point3{ p.x(), p.y(), p.z() };
  };
  std::vector<SurfaceMesh::Halfedge_index> shortest;
  for (SurfaceMesh::Face_index f : surface.faces())
  {
    const SurfaceMesh::Halfedge_index h0 = surface.halfedge(f), h1 = surface.next(h0), h2 = surface.next(h1);
    if (!(smallestAngleCosine(at(surface.target(h0)), at(surface.target(h1)), at(surface.target(h2))) > cos30))
      continue;
    SurfaceMesh::Halfedge_index best = h0;
    for (SurfaceMesh::Halfedge_index h : { h1, h2 })
      if (CGAL::squared_distance(surface.point(surface.source(h)), surface.point(surface.target(h))) <
          CGAL::squared_distance(surface.point(surface.source(best)), surface.point(surface.target(best))))
        best = h;
    if (CGAL::squared_distance(surface.point(surface.source(best)), surface.point(surface.target(best))) <
        0.64 * targetEdgeLength * targetEdgeLength)
      shortest.push_back(best);
  }
  std::vector<Vertex> collapsed;
  for (SurfaceMesh::Halfedge_index h : shortest)
  {
    if (surface.is_removed(h))
      continue;
    const SurfaceMesh::Edge_index e = surface.edge(h);
    const Vertex a = surface.source(h), b = surface.target(h);
    if (!CGAL::Euler::does_satisfy_link_condition(e, surface))
      continue;
    bool touchesConstraint = false;
    for (Vertex v : { a, b })
      for (SurfaceMesh::Halfedge_index around : CGAL::halfedges_around_target(v, surface))
        touchesConstraint = touchesConstraint || constrained[surface.edge(around)];
    if (touchesConstraint)
      continue;
    const Kernel::Point_3 middle = CGAL::midpoint(surface.point(a), surface.point(b));
    // Every triangle around a or b but the two on the edge, with that end at the middle instead.
    bool acceptable = true;
    for (Vertex v : { a, b })
      for (SurfaceMesh::Halfedge_index around : CGAL::halfedges_around_target(v, surface))
      {
        const SurfaceMesh::Face_index f = surface.face(around);
        if (f == SurfaceMesh::null_face() || f == surface.face(h) || f == surface.face(surface.opposite(h)))
          continue;
        const Kernel::Point_3& p = surface.point(surface.source(around));
        const Kernel::Point_3& q = surface.point(surface.target(surface.next(around)));
        const Kernel::Vector_3 before =
          CGAL::cross_product(Kernel::Vector_3(p, surface.point(v)), Kernel::Vector_3(p, q));
        const Kernel::Vector_3 after = CGAL::cross_product(Kernel::Vector_3(p, middle), Kernel::Vector_3(p, q));
        if (!(before * after > 0.0) || CGAL::squared_distance(p, middle) > 4.0 * targetEdgeLength * targetEdgeLength)
          acceptable = false;
      }
    if (!acceptable)
      continue;
    const Vertex kept = CGAL::Euler::collapse_edge(e, surface);
    surface.point(kept) = middle;
    collapsed.push_back(kept);
  }
  return collapsed;
}

Kernel::Point_3 unknownPoint()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return { nan, nan, nan };
}

bool known(const Kernel::Point_3& p)
{
  return !std::isnan(p.x());
}

/** Moves every vertex but the border's to its closest point on the input piece (`grid`), and records
 *  it in `onInput`. The search starts from the vertex's last point on the input, or for a vertex a
 *  split made, a neighbour's: the relaxation moved it a fraction of an edge from there, so the grid
 *  is searched only within that distance. A vertex with no hint at all (none in its connected piece
 *  has one, which the remesh does not make) is still projected right, only slowly.
 *  With `only` (a flag per vertex index), only the vertices flagged are projected. */
template <typename PointMap>
void projectOntoInput(SurfaceMesh& surface, PointMap onInput, const InputGrid& grid, unsigned int threads,
                      const std::vector<char>* only = nullptr)
{
  const std::size_t vertexCount = surface.number_of_vertices();
  std::vector<Kernel::Point_3> hints(vertexCount);
  std::deque<Vertex> reached;
  for (Vertex v : surface.vertices())
  {
    hints[v.idx()] = onInput[v];
    if (known(hints[v.idx()]))
      reached.push_back(v);
  }
  // A long edge split several times leaves new vertices whose neighbours are new too: each takes
  // the hint of the nearest vertex, in edges, that has one.
  for (; !reached.empty(); reached.pop_front())
  {
    const Vertex v = reached.front();
    if (surface.is_isolated(v))
      continue;
    for (Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface))
      if (!known(hints[u.idx()]))
      {
        hints[u.idx()] = hints[v.idx()];
        reached.push_back(u);
      }
  }
  parallelForRanges(vertexCount, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t index = first; index < last; ++index)
                      {
                        const Vertex v(static_cast<SurfaceMesh::size_type>(index));
                        if (surface.is_border(v) || (only && !(*only)[index]))
                          continue;
                        const Kernel::Point_3& p = surface.point(v);
                        surface.point(v) = known(hints[index]) ? grid.closestPoint(p, hints[index]) : grid.closestPoint(p);
                        onInput[v] = surface.point(v);
                      }
                    });
}

/** After the rounds: the shortest edges of the triangles still under 30 degrees collapsed
 *  (collapseNarrowEdges), then the triangles within two rings of each collapse remeshed once more
 *  (the ring around them kept as their border) and their vertices, with those the round adds,
 *  relaxed and projected onto the input. Only there: a round over the whole region cost 4-5% of a
 *  run for the few places that need it. */
template <typename PointMap, typename HeldMap>
void remeshAroundNarrowTriangles(SurfaceMesh& surface,
                                 const SurfaceMesh::Property_map<SurfaceMesh::Edge_index, bool>& constrained,
                                 double targetEdgeLength, PointMap onInput, HeldMap heldOnContour, const InputGrid& grid,
                                 unsigned int threads)
{
  const std::vector<Vertex> collapsed = collapseNarrowEdges(surface, constrained, targetEdgeLength);
  if (collapsed.empty())
    return;
  // Default true: the vertices the round below adds are the patch's too.
  auto inPatch = surface.add_property_map<Vertex, bool>("v:in_patch", true).first;
  for (Vertex v : surface.vertices())
    inPatch[v] = false;
  std::vector<Vertex> ring;
  for (Vertex v : collapsed) // a later collapse can have removed an earlier one's vertex
    if (!surface.is_removed(v) && !surface.is_isolated(v))
    {
      inPatch[v] = true;
      ring.push_back(v);
    }
  for (int rings = 0; rings < 2; ++rings)
  {
    std::vector<Vertex> next;
    for (Vertex v : ring)
      for (Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface))
        if (!inPatch[u])
        {
          inPatch[u] = true;
          next.push_back(u);
        }
    ring.swap(next);
  }
  surface.collect_garbage(); // the property map is compacted with the vertices
  // The patch: the triangles whose corners are all in it. Every edge not between two of them is
  // held for the round, so the ring around the patch stays as it is.
  auto held = surface.add_property_map<SurfaceMesh::Edge_index, bool>("e:held_around_patch", false).first;
  auto inside = [&](SurfaceMesh::Halfedge_index h)
  {
    if (surface.is_border(h))
      return false;
    for (Vertex v : CGAL::vertices_around_face(h, surface))
      if (!inPatch[v])
        return false;
    return true;
  };
  for (SurfaceMesh::Edge_index e : surface.edges())
    held[e] = constrained[e] || !inside(surface.halfedge(e)) || !inside(surface.opposite(surface.halfedge(e)));
  splitCollapseFlip(surface, held, targetEdgeLength);
  surface.remove_property_map(held);
  surface.collect_garbage();
  std::vector<char> moving(surface.number_of_vertices());
  for (Vertex v : surface.vertices())
    moving[v.idx()] = inPatch[v] && !heldOnContour[v];
  surface.remove_property_map(inPatch);
  relaxTangentially(surface, threads, &moving);
  projectOntoInput(surface, onInput, grid, threads, &moving);
}

/** The grid a piece's remesh projects onto (ClosestPointGrid), built on the piece itself, on a thread
 *  of its own beside the remesh's rounds when `alongside`: the rounds need it only for their
 *  projection, after the last one, and built first on one thread it left the other cores idle.
 *  get() waits for it and passes on what the build threw. (Whether the piece fits a manifold
 *  surface is found where each region of it is turned into CGAL's surface to be remeshed: a whole
 *  copy of the piece made only to check that first was a tiling's worth of memory.) */
class ProjectionGrid
{
public:
  ProjectionGrid(const TriangleMesh& mesh, bool alongside)
  {
    if (alongside)
      m_Built = std::async(std::launch::async, [this, &mesh] { m_Grid = std::make_unique<InputGrid>(mesh); }).share();
    else
      m_Grid = std::make_unique<InputGrid>(mesh);
  }

  ProjectionGrid(const ProjectionGrid&) = delete;
  ProjectionGrid& operator=(const ProjectionGrid&) = delete;

  ~ProjectionGrid()
  {
    if (m_Built.valid())
      m_Built.wait(); // the build reads the mesh and writes the grid
  }

  /** Whether the grid is built (get() would not wait). */
  bool built() const
  {
    return !m_Built.valid() || m_Built.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  }

  const InputGrid& get() const
  {
    if (m_Built.valid())
      m_Built.get();
    return *m_Grid;
  }

private:
  std::unique_ptr<InputGrid> m_Grid;
  std::shared_future<void> m_Built;
};

/** Remeshes one region of the input piece (all of it, or a slab or band of it) in two steps: the
 *  rounds, then the finish. Per round, a split, collapse and flip (splitCollapseFlip), then a
 *  relaxation sweep; after the last round, the projection onto the input piece (the grid). A round's
 *  relaxation moves a vertex within its tangent plane by a fraction of an edge, so the rounds between
 *  stay close to a piece many edges across: projecting after each (as Botsch and Kobbelt do) gave the
 *  same distances and triangles within 0.3% for three times the projection's cost. A speck is
 *  projected after each (projectEachRound). Then the triangles still under 30 degrees are remeshed
 *  around (remeshAroundNarrowTriangles). The region's border, where it meets the rest of the piece, is
 *  kept exactly: its edges are neither split nor collapsed, its vertices not moved. The two steps
 *  apart let a region whose rounds end before the grid is built wait without holding a thread
 *  (remeshRegions). Throws Error if the region does not fit a manifold surface. */
class RegionRemesh
{
public:
  RegionRemesh(const MeshRegion& region, const SurfaceRemeshingOptions& options, const ContourStack* heldContours)
    : m_Surface(surfaceOf(region.mesh))
    , m_Options(options)
    , m_HeldContours(heldContours)
  {
    m_Origin = m_Surface.add_property_map<Vertex, std::int32_t>("v:origin", -1).first;
    for (Vertex v : m_Surface.vertices())
      m_Origin[v] = region.origin[v.idx()];
    // Kept: the border and every edge of a triangle that touches it. A flip or collapse next to the
    // border could otherwise join two border vertices by a new edge, which the neighbouring region
    // may have too: four triangles on one edge once the regions are put back together.
    m_Constrained = m_Surface.add_property_map<SurfaceMesh::Edge_index, bool>("e:constrained", false).first;
    for (Vertex v : m_Surface.vertices())
      if (m_Surface.is_border(v))
      {
        for (SurfaceMesh::Face_index f : CGAL::faces_around_target(m_Surface.halfedge(v), m_Surface))
          if (f != SurfaceMesh::null_face())
            for (SurfaceMesh::Halfedge_index h : CGAL::halfedges_around_face(m_Surface.halfedge(f), m_Surface))
              m_Constrained[m_Surface.edge(h)] = true;
      }
    // Drawn contours: their edges are constrained and their vertices neither relaxed nor projected
    // (the passes keep a constrained edge's vertices where they are).
    m_HeldOnContour = m_Surface.add_property_map<Vertex, bool>("v:held_on_contour", false).first;
    // A point on a straight stretch of a contour (above all a crossing point the tiling put on a
    // contour edge, a fraction of an edge from its end) may merge into a neighbour along it, away
    // from the region's border: the contour stays as drawn.
    m_SlidingOnContour = m_Surface.add_property_map<Vertex, bool>("v:sliding_on_contour", false).first;
    if (heldContours)
      holdContourEdges(region.mesh, *heldContours);
    // Every vertex starts on the input piece (the tiling, or slabs already projected onto it).
    m_OnInput = m_Surface.add_property_map<Vertex, Kernel::Point_3>("v:on_input", unknownPoint()).first;
    for (Vertex v : m_Surface.vertices())
      m_OnInput[v] = m_Surface.point(v);
  }

  RegionRemesh(const RegionRemesh&) = delete;
  RegionRemesh& operator=(const RegionRemesh&) = delete;

  /** The rounds but the last one's projection; `grid` is waited for only with projectEachRound. */
  void rounds(const ProjectionGrid& grid, unsigned int threads)
  {
    const ContourVertices contourVertices{ m_HeldOnContour, m_SlidingOnContour };
    for (int round = 0; round < m_Options.iterations; ++round)
    {
      splitCollapseFlip(m_Surface, m_Constrained, m_Options.targetEdgeLength,
                        m_HeldContours ? &contourVertices : nullptr);
      m_Surface.collect_garbage(); // the next round's face index map must be dense
      relaxTangentially(m_Surface, threads, freeVertices()); // the round's vertices, after its garbage went
      if (m_Options.projectEachRound && round + 1 < m_Options.iterations)
        projectOntoInput(m_Surface, m_OnInput, grid.get(), threads, freeVertices());
    }
  }

  /** The last projection and the remesh around narrow triangles: the remeshed region. */
  MeshRegion finish(const InputGrid& grid, unsigned int threads)
  {
    if (m_Options.iterations > 0)
      projectOntoInput(m_Surface, m_OnInput, grid, threads, freeVertices());
    remeshAroundNarrowTriangles(m_Surface, m_Constrained, m_Options.targetEdgeLength, m_OnInput, m_HeldOnContour,
                                grid, threads);
    MeshRegion result;
    result.mesh = toTriangleMesh(m_Surface);
    for (Vertex v : m_Surface.vertices())
      result.origin.push_back(m_Origin[v]);
    return result;
  }

private:
  void holdContourEdges(const TriangleMesh& mesh, const ContourStack& contours)
  {
    const HeldContourEdges held = heldContourEdges(mesh, contours);
    for (Vertex v : m_Surface.vertices())
    {
      m_HeldOnContour[v] = held.vertices[v.idx()] != 0;
      bool nearBorder = false;
      for (SurfaceMesh::Halfedge_index h : CGAL::halfedges_around_target(v, m_Surface))
        nearBorder = nearBorder || m_Constrained[m_Surface.edge(h)];
      m_SlidingOnContour[v] = held.straight[v.idx()] != 0 && !nearBorder;
    }
    for (const auto& [a, b] : held.edges)
    {
      const SurfaceMesh::Halfedge_index h = m_Surface.halfedge(Vertex(static_cast<SurfaceMesh::size_type>(a)),
                                                               Vertex(static_cast<SurfaceMesh::size_type>(b)));
      if (h != SurfaceMesh::null_halfedge())
        m_Constrained[m_Surface.edge(h)] = true;
    }
  }

  /** The vertices the relaxation and projection may move (null: all but the border's). */
  const std::vector<char>* freeVertices()
  {
    if (!m_HeldContours)
      return nullptr;
    m_Movable.assign(m_Surface.number_of_vertices(), 0);
    for (Vertex v : m_Surface.vertices())
      m_Movable[v.idx()] = !m_HeldOnContour[v];
    return &m_Movable;
  }

  SurfaceMesh m_Surface;
  const SurfaceRemeshingOptions& m_Options;
  const ContourStack* m_HeldContours;
  SurfaceMesh::Property_map<Vertex, std::int32_t> m_Origin;
  SurfaceMesh::Property_map<SurfaceMesh::Edge_index, bool> m_Constrained;
  SurfaceMesh::Property_map<Vertex, bool> m_HeldOnContour;
  SurfaceMesh::Property_map<Vertex, bool> m_SlidingOnContour;
  SurfaceMesh::Property_map<Vertex, Kernel::Point_3> m_OnInput;
  std::vector<char> m_Movable;
};

/** One region remeshed (RegionRemesh), both steps at once. */
MeshRegion remeshRegion(const MeshRegion& region, const SurfaceRemeshingOptions& options, const ProjectionGrid& grid,
                        unsigned int threads, const ContourStack* heldContours)
{
  RegionRemesh remesh(region, options, heldContours);
  remesh.rounds(grid, threads);
  return remesh.finish(grid.get(), threads);
}

/** Remeshes the regions of `mesh` (regionOf, -1: left alone) side by side; a region that cannot be
 *  remeshed is kept as it was when `keepFailed`, else the whole call throws. A region whose rounds
 *  end before the grid is built waits for its finish until all have had their rounds: the threads
 *  go on with other regions meanwhile instead of waiting with the one building the grid. The regions
 *  start most work first (mostWorkFirst); each goes into its own slot, whatever the order. (When
 *  several throw, the one rethrown is the first in that order: fixed by the mesh, not the threads.) */
TriangleMesh remeshRegions(const TriangleMesh& mesh, const std::vector<int>& regionOf, int count,
                           const SurfaceRemeshingOptions& options, const ProjectionGrid& grid, unsigned int threads,
                           bool keepFailed, const ContourStack* heldContours)
{
  std::vector<MeshRegion> regions(static_cast<std::size_t>(count));
  std::vector<std::unique_ptr<RegionRemesh>> waiting(regions.size());
  const RegionTriangles byRegion = trianglesByRegion(regionOf, count);
  auto cutOut = [&](std::size_t r)
  { return extractRegion(mesh, byRegion.ids.data() + byRegion.first[r], byRegion.ids.data() + byRegion.first[r + 1]); };
  auto remeshed = [&](std::size_t r, auto&& step)
  {
    try
    {
      step();
    }
    catch (const std::exception&)
    {
      if (!keepFailed)
        throw;
      waiting[r].reset();
      regions[r] = cutOut(r);
    }
  };
  const std::vector<std::size_t> order = mostWorkFirst(mesh, regionOf, count, options.targetEdgeLength);
  parallelFor(regions.size(), threads,
              [&](std::size_t i)
              {
                const std::size_t r = order[i];
                remeshed(r,
                         [&]
                         {
                           auto remesh = std::make_unique<RegionRemesh>(cutOut(r), options, heldContours);
                           remesh->rounds(grid, 1);
                           if (grid.built())
                             regions[r] = remesh->finish(grid.get(), 1);
                           else
                             waiting[r] = std::move(remesh);
                         });
              });
  parallelFor(regions.size(), threads,
              [&](std::size_t i)
              {
                const std::size_t r = order[i];
                if (waiting[r])
                  remeshed(r, [&] { regions[r] = waiting[r]->finish(grid.get(), 1); });
                waiting[r].reset();
              });
  return reassembleRegions(mesh, regionOf, regions);
}

/** Rings each side of a seam between slabs remeshed again as a band: the band's own border then
 *  lies among remeshed triangles. */
constexpr int bandRings = 3;

/** How tall a slab is at least, in target edges: a band reaches bandRings rings each side of its
 *  seam, each remeshed ring at most one long edge (4/3 of the target: longer ones are split), so
 *  bands around the two seams of a slab this tall stay two edges apart (the tiled triangles each
 *  slab keeps along its border can be longer, a slice spacing between thick slices: there the
 *  margin is smaller; on the scaling benchmark's volumes no two bands met). Two bands that met would
 *  be one region, remeshed on one thread; the mesh would be no worse. */
constexpr double slabEdges = 2.0 * bandRings * 4.0 / 3.0 + 2.0;

/** The triangles not flagged in `keep` (none: every triangle) as one region, remeshed around the
 *  kept ones, whose border is kept exactly as between slabs. */
TriangleMesh remeshedAsOneRegion(const TriangleMesh& mesh, const std::vector<char>* keep, const SurfaceRemeshingOptions& options,
                                 const ProjectionGrid& grid, unsigned int threads, const ContourStack* heldContours)
{
  if (!keep)
  {
    MeshRegion whole{ mesh, {} };
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      whole.origin.push_back(static_cast<std::int32_t>(v));
    return remeshRegion(whole, options, grid, threads, heldContours).mesh;
  }
  std::vector<int> regionOf(mesh.triangles.size());
  for (std::size_t t = 0; t < keep->size(); ++t)
    regionOf[t] = (*keep)[t] ? -1 : 0;
  const std::vector<MeshRegion> remeshed{ remeshRegion(extractRegion(mesh, regionOf, 0), options, grid, threads, heldContours) };
  return withoutUnusedVertices(reassembleRegions(mesh, regionOf, remeshed));
}

/** Remeshes one connected, closed piece, projecting onto it, except the triangles flagged in `keep`
 *  (if given), which stay as they are. A large piece is remeshed in slabs side by side, their seams
 *  kept, then in bands around the seams, side by side, so that no trace of the seams is left; the
 *  slabs and bands depend on the piece only, never on the threads. Kept triangles belong to no slab
 *  and no band: each region's border with them is kept, as its border with another region is. */
TriangleMesh remeshPiece(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options, unsigned int threads,
                         const ContourStack* heldContours, const std::vector<char>* keep = nullptr)
{
  const ProjectionGrid grid(mesh, threadCount(threads) > 1);
  const std::size_t perRegion = options.trianglesPerRegion;
  int slabs = 1;
  std::vector<int> slabOf = perRegion == 0 || mesh.triangles.size() < 2 * perRegion
                              ? std::vector<int>()
                              : slabRegions(mesh, perRegion, slabEdges * options.targetEdgeLength, slabs);
  if (slabs == 1) // small, or too flat for two slabs
    return remeshedAsOneRegion(mesh, keep, options, grid, threads, heldContours);
  std::vector<char> seam = seamVertices(mesh, slabOf); // between slabs, not around kept triangles
  std::size_t kept = 0;
  if (keep)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if ((*keep)[t])
      {
        slabOf[t] = -1;
        ++kept;
      }
  TriangleMesh slabbed;
  try
  {
    slabbed = remeshRegions(mesh, slabOf, slabs, options, grid, threads, /*keepFailed=*/false, heldContours);
  }
  catch (const std::exception&) // a slab that is no manifold surface on its own (two fans at a vertex)
  {
    return remeshedAsOneRegion(mesh, keep, options, grid, threads, heldContours);
  }
  seam.resize(slabbed.points.size(), 0); // the slabs' own vertices come after the piece's
  int bands = 0;
  std::vector<int> bandOf = seamBands(slabbed, seam, bandRings, bands);
  // The kept triangles come first in the reassembled mesh (reassembleRegions), in their order.
  std::fill(bandOf.begin(), bandOf.begin() + static_cast<std::ptrdiff_t>(kept), -1);
  const TriangleMesh banded =
    remeshRegions(slabbed, bandOf, bands, options, grid, threads, /*keepFailed=*/true, heldContours);
  slabbed = TriangleMesh(); // not held beside the banded mesh and its copy without unused vertices
  return withoutUnusedVertices(banded);
}

/** Throws unless the target edge length is positive and finite; whether there is anything to do
 *  (rounds asked, triangles to remesh). */
bool remeshingAsked(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options)
{
  if (!(options.targetEdgeLength > 0.0) || !std::isfinite(options.targetEdgeLength))
    throw Error("surface remeshing: the target edge length must be positive");
  return options.iterations > 0 && !mesh.triangles.empty();
}

} // namespace

TriangleMesh remeshSurface(const TriangleMesh& mesh, const SurfaceRemeshingOptions& options, unsigned int threads,
                           const ContourStack* heldContours)
{
  if (!remeshingAsked(mesh, options))
    return mesh;
  // Piece by piece: each vertex is projected back onto its own piece, never onto a neighbour.
  // A mesh that is one piece (what finishSurface hands over) is its own piece: no copy of it is held.
  std::size_t components = 0;
  vertexComponents(mesh, components);
  if (components == 1)
    return remeshPiece(mesh, options, threads, heldContours);
  std::vector<TriangleMesh> pieces = splitIntoPieces(mesh);
  for (TriangleMesh& piece : pieces)
    piece = remeshPiece(piece, options, threads, heldContours);
  if (pieces.size() == 1)
    return std::move(pieces.front());
  std::vector<const TriangleMesh*> remeshed;
  for (const TriangleMesh& piece : pieces)
    remeshed.push_back(&piece);
  return joinMeshes(remeshed);
}

TriangleMesh remeshSurfaceAround(const TriangleMesh& mesh, const std::vector<char>& keep,
                                 const SurfaceRemeshingOptions& options, unsigned int threads,
                                 const ContourStack* heldContours)
{
  if (keep.size() != mesh.triangles.size())
    throw Error("surface remeshing: one keep flag per triangle is needed");
  if (!remeshingAsked(mesh, options))
    return mesh;
  // In slabs and bands side by side as the first remesh: as one region, a large piece's remesh
  // around its crossings ran on one thread.
  return remeshPiece(mesh, options, threads, heldContours, &keep);
}

double voxelFaceEdgeLength(const std::array<double, 3>& spacing)
{
  const double sx = spacing[0], sy = spacing[1], sz = spacing[2];
  if (!(sx > 0.0 && sy > 0.0 && sz > 0.0))
    throw Error("surface remeshing: the voxel spacing must be positive");
  return std::sqrt(3.0 / (1.0 / (sx * sy) + 1.0 / (sx * sz) + 1.0 / (sy * sz)));
}

double facingEdgeLength(const TriangleMesh& surface, const std::array<double, 3>& spacing)
{
  voxelFaceEdgeLength(spacing); // the same checks
  // Each triangle's cross product is twice its area times its unit normal: summed by axis, its
  // components' magnitudes are twice the integral of |n_i|, its length twice the area.
  double projected[3] = { 0.0, 0.0, 0.0 };
  double area = 0.0;
  for (const Triangle& t : surface.triangles)
  {
    const Point3 n = areaNormal(surface, t);
    projected[0] += std::abs(n.x);
    projected[1] += std::abs(n.y);
    projected[2] += std::abs(n.z);
    area += std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  }
  const double sx = spacing[0], sy = spacing[1], sz = spacing[2];
  // The crossings along axis i are the integral of |n_i| over s_j s_k; two triangles a crossing.
  const double flyingEdgesTriangles = projected[0] / (sy * sz) + projected[1] / (sx * sz) + projected[2] / (sx * sy);
  if (!(area > 0.0) || !(flyingEdgesTriangles > 0.0))
    return 0.0;
  // A remesh at edge length L makes about 3 A / L^2 triangles (voxelFaceEdgeLength's relation).
  return std::sqrt(3.0 * 0.5 * area / flyingEdgesTriangles);
}

double automaticEdgeLength(const std::array<double, 3>& spacing)
{
  return 1.1 * voxelFaceEdgeLength(spacing);
}

} // namespace slicemesh

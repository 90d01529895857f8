// One round of split, collapse and flip: on a latitude-longitude sphere (long edges at the equator,
// needles at the poles) it does what a round of CGAL's isotropic remeshing does and leaves a valid
// surface on the sphere; on a dome with its border held, the triangles touching the border stay as
// they are; twice on one mesh, it gives the same mesh.
#include "Finishing/RemeshingPasses.h"
#include "Measures/MeshValidation.h"

#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <set>
#include <tuple>
#include <utility>

using namespace slicemesh;

namespace
{

TriangleMesh sphere(double radius, int rings, int sectors)
{
  TriangleMesh mesh;
  mesh.points.push_back({ 0.0, 0.0, -radius });
  for (int r = 1; r < rings; ++r)
  {
    const double polar = M_PI * r / rings;
    for (int s = 0; s < sectors; ++s)
    {
      const double azimuth = 2.0 * M_PI * s / sectors;
      mesh.points.push_back({ radius * std::sin(polar) * std::cos(azimuth), radius * std::sin(polar) * std::sin(azimuth),
                              -radius * std::cos(polar) });
    }
  }
  mesh.points.push_back({ 0.0, 0.0, radius });
  const auto top = static_cast<std::int32_t>(mesh.points.size() - 1);
  auto at = [&](int r, int s) { return static_cast<std::int32_t>(1 + (r - 1) * sectors + (s % sectors)); };
  for (int s = 0; s < sectors; ++s)
  {
    mesh.triangles.push_back({ 0, at(1, s + 1), at(1, s) });
    mesh.triangles.push_back({ top, at(rings - 1, s), at(rings - 1, s + 1) });
    for (int r = 1; r + 1 < rings; ++r)
    {
      mesh.triangles.push_back({ at(r, s), at(r, s + 1), at(r + 1, s) });
      mesh.triangles.push_back({ at(r, s + 1), at(r + 1, s + 1), at(r + 1, s) });
    }
  }
  return mesh;
}

/** A square of n x n cells of side `cell`, two triangles a cell, gently domed (z up to 1). */
TriangleMesh dome(int n, double cell)
{
  TriangleMesh mesh;
  const double half = 0.5 * n * cell;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      const double x = i * cell - half, y = j * cell - half;
      mesh.points.push_back({ x, y, 1.0 - (x * x + y * y) / (2.0 * half * half) });
    }
  auto at = [&](int i, int j) { return static_cast<std::int32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      mesh.triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      mesh.triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  return mesh;
}

TriangleMesh asTriangleMesh(CgalSurfaceMesh& surface)
{
  surface.collect_garbage();
  TriangleMesh mesh;
  for (CgalSurfaceMesh::Vertex_index v : surface.vertices())
    mesh.points.push_back({ surface.point(v).x(), surface.point(v).y(), surface.point(v).z() });
  for (CgalSurfaceMesh::Face_index f : surface.faces())
  {
    Triangle t{};
    int corner = 0;
    for (CgalSurfaceMesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      t[corner++] = static_cast<std::int32_t>(v.idx());
    mesh.triangles.push_back(t);
  }
  return mesh;
}

/** One round at `target`, the edges for which `hold` says so held. */
template <typename Hold>
TriangleMesh oneRound(const TriangleMesh& mesh, double target, Hold hold)
{
  CgalSurfaceMesh surface;
  EXPECT_EQ(toSurfaceMesh(mesh, surface), mesh.triangles.size());
  auto constrained = surface.add_property_map<CgalSurfaceMesh::Edge_index, bool>("e:constrained", false).first;
  for (CgalSurfaceMesh::Edge_index e : surface.edges())
    constrained[e] = hold(surface, e);
  splitCollapseFlip(surface, constrained, target);
  return asTriangleMesh(surface);
}

struct EdgeStatistics
{
  double withinBounds = 0.0; ///< share of the edges between 4/5 and 4/3 of the target
};

EdgeStatistics statisticsOf(const TriangleMesh& mesh, double target)
{
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert({ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) });
  std::size_t within = 0;
  for (const auto& [a, b] : edges)
  {
    const Point3 &p = mesh.points[a], &q = mesh.points[b];
    const double length = std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z));
    within += length >= 0.8 * target && length <= 4.0 / 3.0 * target;
  }
  EdgeStatistics s;
  s.withinBounds = static_cast<double>(within) / static_cast<double>(edges.size());
  return s;
}

} // namespace

TEST(RemeshingPasses, DoOnASphereWhatCgalsRoundDoes)
{
  // A latitude-longitude sphere: edges of 0.2 to 2.6 mm, needles at the poles, a fifth of the
  // triangles under 30 degrees. One round at four targets against one round of CGAL's
  // isotropic_remeshing (no relaxation, no projection), whose rules the passes follow.
  const double radius = 20.0;
  const TriangleMesh before = sphere(radius, 40, 48);
  const MeshValidation was = validateMesh(before);
  ASSERT_GT(was.fractionAnglesBelow30, 0.2);
  for (double target : { 1.0, 1.5, 2.0, 2.5 })
  {
    SCOPED_TRACE("target " + std::to_string(target));
    const TriangleMesh after = oneRound(before, target, [](const CgalSurfaceMesh&, CgalSurfaceMesh::Edge_index) { return false; });
    CgalSurfaceMesh reference;
    toSurfaceMesh(before, reference);
    CGAL::Polygon_mesh_processing::isotropic_remeshing(
      faces(reference), target, reference,
      CGAL::parameters::number_of_iterations(1).number_of_relaxation_steps(0).do_project(false));
    const TriangleMesh cgal = asTriangleMesh(reference);

    const MeshValidation v = validateMesh(after), c = validateMesh(cgal);
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_EQ(v.eulerCharacteristic, 2);
    EXPECT_NEAR(static_cast<double>(after.triangles.size()), static_cast<double>(cgal.triangles.size()),
                0.02 * static_cast<double>(cgal.triangles.size()));
    EXPECT_LE(v.fractionAnglesBelow30, c.fractionAnglesBelow30 + 0.01);
    EXPECT_GT(v.minAngleDegrees, 2.0 * was.minAngleDegrees - 3.0); // the poles' needles are gone
    EXPECT_GE(statisticsOf(after, target).withinBounds, statisticsOf(cgal, target).withinBounds - 0.02);
    // Splits put points on chords and collapses keep one end: the surface stays within the
    // polyhedron, whose chords of at most 3 mm lie within 0.1 mm of the sphere.
    for (const Point3& p : after.points)
    {
      const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
      EXPECT_LE(r, radius + 1e-9);
      EXPECT_GE(r, radius - 0.1);
    }
    EXPECT_NEAR(v.volume, was.volume, 0.01 * was.volume);
    // Against the sphere itself: inside it, and within 1% of its volume (the input polyhedron
    // holds 99.56% of it, one round 99.48-99.54% at these targets).
    const double sphereVolume = 4.0 / 3.0 * M_PI * radius * radius * radius;
    EXPECT_LT(v.volume, sphereVolume);
    EXPECT_GT(v.volume, 0.99 * sphereVolume);
  }
}

TEST(RemeshingPasses, KeepTheBorderAndTheTrianglesTouchingItWhenHeld)
{
  const TriangleMesh before = dome(24, 0.25); // edges of 0.25-0.35, remeshed at 1
  // Held: every edge of a triangle with a corner on the border, as the remesh of a slab holds them.
  auto hold = [](const CgalSurfaceMesh& surface, CgalSurfaceMesh::Edge_index e)
  {
    for (CgalSurfaceMesh::Halfedge_index side : { surface.halfedge(e), surface.opposite(surface.halfedge(e)) })
      if (!surface.is_border(side))
        for (CgalSurfaceMesh::Vertex_index v : CGAL::vertices_around_face(side, surface))
          if (surface.is_border(v))
            return true;
    return false;
  };
  const TriangleMesh after = oneRound(before, 1.0, hold);

  // The triangles touching the border, by their corners' positions, are all there after.
  auto key = [](const TriangleMesh& mesh, const Triangle& t)
  {
    std::array<std::tuple<double, double, double>, 3> corners;
    for (int k = 0; k < 3; ++k)
      corners[k] = { mesh.points[t[k]].x, mesh.points[t[k]].y, mesh.points[t[k]].z };
    std::sort(corners.begin(), corners.end());
    return corners;
  };
  std::set<std::array<std::tuple<double, double, double>, 3>> afterTriangles;
  for (const Triangle& t : after.triangles)
    afterTriangles.insert(key(after, t));
  const double half = 3.0;
  std::size_t touching = 0;
  for (const Triangle& t : before.triangles)
  {
    const bool onBorder = std::any_of(t.begin(), t.end(), [&](std::int32_t v)
                                      { return std::abs(std::abs(before.points[v].x) - half) < 1e-12 ||
                                               std::abs(std::abs(before.points[v].y) - half) < 1e-12; });
    if (!onBorder)
      continue;
    ++touching;
    EXPECT_EQ(afterTriangles.count(key(before, t)), 1u);
  }
  EXPECT_EQ(touching, 2u * (4u * 24u - 4u)); // both triangles of each cell along the border
  const MeshValidation v = validateMeshTopology(after);
  EXPECT_TRUE(v.manifold());
  EXPECT_EQ(v.degenerateTriangles, 0u);
  EXPECT_EQ(v.boundaryEdges, 4u * 24u);
  EXPECT_LT(after.triangles.size(), before.triangles.size() / 3); // the inside was coarsened
}

TEST(RemeshingPasses, GiveTheSameMeshTwice)
{
  const TriangleMesh before = sphere(10.0, 30, 37);
  auto none = [](const CgalSurfaceMesh&, CgalSurfaceMesh::Edge_index) { return false; };
  const TriangleMesh first = oneRound(before, 1.5, none), second = oneRound(before, 1.5, none);
  ASSERT_EQ(first.triangles.size(), second.triangles.size());
  EXPECT_EQ(first.triangles, second.triangles);
  for (std::size_t v = 0; v < first.points.size(); ++v)
    EXPECT_TRUE(first.points[v].x == second.points[v].x && first.points[v].y == second.points[v].y &&
                first.points[v].z == second.points[v].z);
}

#include "ContourStacks.h"
#include "SameValidation.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>

using namespace slicemesh;
using slicemesh::testing::expectSameValidation;

namespace
{
// A unit tetrahedron, outward oriented.
TriangleMesh tetrahedron()
{
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  mesh.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } };
  return mesh;
}
} // namespace

TEST(MeshValidation, TetrahedronIsValid)
{
  const MeshValidation v = validateMesh(tetrahedron());
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_NEAR(v.volume, 1.0 / 6.0, 1e-12);
  EXPECT_EQ(v.eulerCharacteristic, 2);
  EXPECT_EQ(v.components, 1u);
}

TEST(MeshValidation, DetectsHolesFlipsAndNonManifoldEdges)
{
  TriangleMesh open = tetrahedron();
  open.triangles.pop_back();
  EXPECT_EQ(validateMesh(open).boundaryEdges, 3u);

  TriangleMesh flipped = tetrahedron();
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_GT(validateMesh(flipped).inconsistentEdges, 0u);

  TriangleMesh inverted = tetrahedron();
  for (Triangle& t : inverted.triangles)
    std::swap(t[1], t[2]);
  EXPECT_FALSE(validateMesh(inverted).oriented()) << "inward normals give a negative volume";

  TriangleMesh fin = tetrahedron();
  fin.points.push_back({ 1, 1, -1 });
  fin.triangles.push_back({ 0, 1, 4 });
  EXPECT_EQ(validateMesh(fin).nonManifoldEdges, 1u);
}

TEST(MeshValidation, DetectsSelfIntersectionAndNonManifoldVertex)
{
  // Two tetrahedra sharing only a vertex: closed, but the vertex is not manifold.
  TriangleMesh touching = tetrahedron();
  touching.points.push_back({ -1, 0, 0 });
  touching.points.push_back({ 0, -1, 0 });
  touching.points.push_back({ 0, 0, -1 });
  touching.triangles.push_back({ 0, 5, 4 });
  touching.triangles.push_back({ 0, 4, 6 });
  touching.triangles.push_back({ 4, 5, 6 });
  touching.triangles.push_back({ 0, 6, 5 });
  EXPECT_EQ(validateMesh(touching).nonManifoldVertices, 1u);

  // Two tetrahedra that overlap in space.
  TriangleMesh overlapping = tetrahedron();
  const TriangleMesh second = tetrahedron();
  for (const Point3& p : second.points)
    overlapping.points.push_back({ p.x + 0.2, p.y + 0.2, p.z + 0.2 });
  for (const Triangle& t : second.triangles)
    overlapping.triangles.push_back({ t[0] + 4, t[1] + 4, t[2] + 4 });
  const MeshValidation v = validateMesh(overlapping);
  EXPECT_TRUE(v.selfIntersectionChecked);
  EXPECT_GT(v.selfIntersections, 0u);
  EXPECT_FALSE(v.valid());
}

TEST(MeshValidation, CountsFoldsThatNoTrianglesCrossYet)
{
  // A tetrahedron squashed until its apex is a hair above the base: closed, oriented and, exactly,
  // free of crossings, but its three side faces fold onto the base (dihedral angles near 0).
  TriangleMesh squashed = tetrahedron();
  squashed.points[3] = { 0.3, 0.3, 1e-9 };
  const MeshValidation v = validateMesh(squashed);
  EXPECT_TRUE(v.closed() && v.manifold() && v.oriented()) << v.summary();
  EXPECT_EQ(v.foldedEdges, 3u);
  EXPECT_NE(v.summary().find("3 folded edges"), std::string::npos) << v.summary();
  // Steep but open: an apex at 0.02 gives dihedral angles of a few degrees, not a fold.
  squashed.points[3] = { 0.3, 0.3, 0.02 };
  EXPECT_EQ(validateMesh(squashed).foldedEdges, 0u);
}

namespace
{

/** A closed ball of `radius` mm about (cx, 0, 0), sliced every radius / 4 mm, facing out (or in). */
TriangleMesh tiledBall(double cx, double radius, bool facingIn = false)
{
  TriangleMesh mesh = reconstructSurface(slicemesh::testing::ballStack(cx, 0.0, 0.0, radius, 48, radius / 4.0));
  if (facingIn)
    for (Triangle& t : mesh.triangles)
      std::swap(t[1], t[2]);
  return mesh;
}


} // namespace

// Points moved on a mesh of three components (a ball, a cavity inside it, a ball apart), small moves
// and moves that make sheets cross, fold triangles onto each other, flatten them and turn a whole
// component inside out: the validation after moving points is the whole validation, field by field,
// and crossing pair by pair, each time from the validation before it, as a put-back loop chains them.
TEST(MeshValidation, AfterMovingPointsIsTheWholeValidation)
{
  const TriangleMesh outer = tiledBall(0.0, 8.0), cavity = tiledBall(0.0, 4.0, true), apart = tiledBall(30.0, 3.0);
  TriangleMesh mesh = joinMeshes({ &outer, &cavity, &apart });
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  MeshValidation before = validateMesh(mesh, crossings);
  ASSERT_TRUE(before.valid()) << before.summary();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t foldsSeen = 0, crossingsSeen = 0, degenerateSeen = 0, checked = 0;
  for (const double reach : { 0.01, 0.3, 2.0 })
    for (int trial = 0; trial < 6; ++trial)
    {
      std::vector<char> moved(mesh.points.size(), 0);
      for (int k = 0; k < 20; ++k)
      {
        const std::size_t v = std::uniform_int_distribution<std::size_t>(0, mesh.points.size() - 1)(random);
        moved[v] = 1;
        Point3& p = mesh.points[v];
        if (trial == 5) // onto a neighbour: a triangle without area
        {
          for (const Triangle& t : mesh.triangles)
            if (t[0] == static_cast<std::int32_t>(v))
            {
              p = mesh.points[static_cast<std::size_t>(t[1])];
              break;
            }
        }
        else
          p = { p.x + reach * unit(random), p.y + reach * unit(random), p.z + reach * unit(random) };
      }
      std::vector<std::pair<std::size_t, std::size_t>> wholeCrossings;
      const MeshValidation whole = validateMesh(mesh, wholeCrossings);
      const MeshValidation after = validateMeshAfterMovingPoints(mesh, before, moved, crossings);
      expectSameValidation(after, whole, "reach " + std::to_string(reach) + ", trial " + std::to_string(trial));
      EXPECT_EQ(crossings, wholeCrossings);
      foldsSeen += whole.foldedEdges;
      crossingsSeen += whole.selfIntersections;
      degenerateSeen += whole.degenerateTriangles;
      checked += before.foldedEdges == 0; // the shortcut applied (a fold before sends it to the whole check)
      before = after;
    }
  // The moves reached every case: crossings, folds and triangles without area.
  EXPECT_GT(crossingsSeen, 0u);
  EXPECT_GT(foldsSeen, 0u);
  EXPECT_GT(degenerateSeen, 0u);
  EXPECT_GT(checked, 5u);

  // The whole component apart turned inside out by moving its points through its centre.
  mesh = joinMeshes({ &outer, &cavity, &apart });
  before = validateMesh(mesh, crossings);
  std::vector<char> moved(mesh.points.size(), 0);
  const std::size_t firstOfApart = outer.points.size() + cavity.points.size();
  for (std::size_t v = firstOfApart; v < mesh.points.size(); ++v)
  {
    Point3& p = mesh.points[v];
    p = { 60.0 - p.x, -p.y, -p.z };
    moved[v] = 1;
  }
  std::vector<std::pair<std::size_t, std::size_t>> wholeCrossings;
  const MeshValidation whole = validateMesh(mesh, wholeCrossings);
  EXPECT_EQ(whole.misorientedComponents, 1u);
  expectSameValidation(validateMeshAfterMovingPoints(mesh, before, moved, crossings), whole, "inside out");
}

namespace
{

/** The topology counts of validateMeshTopology taken from their definitions, edge by edge and
 *  vertex by vertex, with ordered maps: what the one pass over each vertex's corners must give. */
struct TopologyByDefinition
{
  std::size_t boundary = 0, nonManifold = 0, inconsistent = 0, folded = 0, nonManifoldVertices = 0;
  long eulerCharacteristic = 0;
};

TopologyByDefinition topologyByDefinition(const TriangleMesh& mesh)
{
  TopologyByDefinition d;
  // Every directed edge of every triangle, under its two ends (lower first): its triangle, its way.
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::size_t, bool>>> uses;
  std::map<std::int32_t, std::vector<std::pair<std::int32_t, std::int32_t>>> links; // the edges opposite each vertex
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
    {
      const std::int32_t p = t[i], q = t[(i + 1) % 3];
      uses[{ std::min(p, q), std::max(p, q) }].push_back({ f, p < q });
      links[p].push_back({ t[(i + 1) % 3], t[(i + 2) % 3] });
    }
  }
  auto unitNormal = [&](std::size_t f)
  {
    const Triangle& t = mesh.triangles[f];
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const std::array<double, 3> n{ uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return length > 0.0 ? std::array<double, 3>{ n[0] / length, n[1] / length, n[2] / length }
                        : std::array<double, 3>{ 0.0, 0.0, 0.0 };
  };
  for (auto& [edge, its] : uses)
  {
    std::sort(its.begin(), its.end());
    const std::size_t forward = static_cast<std::size_t>(std::count_if(its.begin(), its.end(), [](const auto& u) { return u.second; }));
    const std::size_t backward = its.size() - forward;
    d.boundary += its.size() == 1;
    d.nonManifold += its.size() > 2;
    d.inconsistent += (forward > 1 ? forward - 1 : 0) + (backward > 1 ? backward - 1 : 0);
    const std::array<double, 3> m = unitNormal(its.front().first); // against the edge's first triangle
    for (std::size_t j = 1; j < its.size(); ++j)
    {
      const std::array<double, 3> n = unitNormal(its[j].first);
      d.folded += m[0] * n[0] + m[1] * n[1] + m[2] * n[2] < -std::cos(M_PI / 180.0);
    }
  }
  for (const auto& [vertex, link] : links)
  {
    // The link's vertices joined by its edges: more than one group, more than one fan.
    std::map<std::int32_t, std::int32_t> group;
    for (const auto& [a, b] : link)
      group[a] = a, group[b] = b;
    for (bool changed = true; changed;)
    {
      changed = false;
      for (const auto& [a, b] : link)
        if (group[a] != group[b])
        {
          group[a] = group[b] = std::min(group[a], group[b]);
          changed = true;
        }
    }
    std::set<std::int32_t> groups;
    for (const auto& entry : group)
      groups.insert(entry.second);
    d.nonManifoldVertices += groups.size() > 1;
  }
  d.eulerCharacteristic =
    static_cast<long>(links.size()) - static_cast<long>(uses.size()) + static_cast<long>(mesh.triangles.size());
  return d;
}

} // namespace

// A closed ball and its faults: triangles gone (holes), repeated (fins), turned over, with a corner
// twice or three times (edges from a vertex to itself), vertices merged (pinched fans) and moved
// onto a neighbour's far side (folds). The counts of validateMeshTopology are each edge's and each
// vertex's own, by their definitions, on every variant.
TEST(MeshValidation, TopologyCountsAreThoseOfEachEdgeAndVertexByDefinition)
{
  const TriangleMesh ball = tiledBall(0.0, 8.0);
  std::mt19937 random(11);
  auto any = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
  std::size_t seen[6] = {};
  for (int trial = 0; trial < 40; ++trial)
  {
    TriangleMesh mesh = ball;
    for (int fault = 0; fault < 1 + trial % 7; ++fault)
    {
      const std::size_t f = any(mesh.triangles.size());
      Triangle& t = mesh.triangles[f];
      switch (any(6))
      {
        case 0: mesh.triangles.erase(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(f)); break;
        case 1: mesh.triangles.push_back(t); break;
        case 2: std::swap(t[1], t[2]); break;
        case 3: t[any(3)] = t[any(3)]; break;
        case 4: // a vertex merged into another anywhere on the ball
        {
          const auto from = static_cast<std::int32_t>(any(mesh.points.size()));
          const auto to = static_cast<std::int32_t>(any(mesh.points.size()));
          for (Triangle& each : mesh.triangles)
            for (std::int32_t& corner : each)
              corner = corner == from ? to : corner;
          break;
        }
        default: // a corner moved through the opposite edge, beyond its neighbour: a fold
        {
          const Point3 a = mesh.points[t[1]], b = mesh.points[t[2]], c = mesh.points[t[0]];
          mesh.points[t[0]] = { a.x + b.x - c.x, a.y + b.y - c.y, a.z + b.z - c.z };
        }
      }
    }
    if (trial % 4 == 0) // a triangle with a corner twice, each way, and one with it three times
    {
      const auto p = static_cast<std::int32_t>(any(mesh.points.size()));
      const auto q = static_cast<std::int32_t>(any(mesh.points.size()));
      const Triangle degenerate[] = { { p, p, q }, { p, q, p }, { q, p, p }, { p, p, p } };
      mesh.triangles.push_back(degenerate[(trial / 4) % 4]);
    }
    const MeshValidation v = validateMeshTopology(mesh);
    const TopologyByDefinition d = topologyByDefinition(mesh);
    const std::string where = "trial " + std::to_string(trial);
    EXPECT_EQ(v.boundaryEdges, d.boundary) << where;
    EXPECT_EQ(v.nonManifoldEdges, d.nonManifold) << where;
    EXPECT_EQ(v.inconsistentEdges, d.inconsistent) << where;
    EXPECT_EQ(v.foldedEdges, d.folded) << where;
    EXPECT_EQ(v.nonManifoldVertices, d.nonManifoldVertices) << where;
    EXPECT_EQ(v.eulerCharacteristic, d.eulerCharacteristic) << where;
    const std::size_t counts[6] = { d.boundary, d.nonManifold, d.inconsistent, d.folded, d.nonManifoldVertices,
                                    v.degenerateTriangles };
    for (int k = 0; k < 6; ++k)
      seen[k] += counts[k];
  }
  // Every kind of fault was met.
  for (int k = 0; k < 6; ++k)
    EXPECT_GT(seen[k], 0u) << "count " << k;
}

// Flips without a link check, collapses, holes, fins and moved points, a few together in one place of
// a mesh of three components (a ball, a cavity inside it, a ball apart), the unused vertices then
// dropped and the rest renumbered: the validation after a local change is the whole validation, field
// by field and crossing pair by crossing pair, given the corners of every triangle that changed.
TEST(MeshValidation, AfterALocalChangeIsTheWholeValidation)
{
  const TriangleMesh outer = tiledBall(0.0, 8.0), cavity = tiledBall(0.0, 4.0, true), apart = tiledBall(30.0, 3.0);
  const TriangleMesh closed = joinMeshes({ &outer, &cavity, &apart });
  // And from a mesh with a hole (the ball apart's last triangle gone): its edges are gathered whole,
  // its crossings still tested around the change only.
  TriangleMesh holed = closed;
  holed.triangles.pop_back();
  std::mt19937 random(5);
  auto any = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
  std::size_t seen[7] = {};
  for (int trial = 0; trial < 120; ++trial)
  {
    const TriangleMesh& joined = trial % 2 == 0 ? closed : holed;
    std::vector<std::pair<std::size_t, std::size_t>> crossings;
    const MeshValidation before = validateMesh(joined, crossings);
    ASSERT_TRUE(before.selfIntersectionChecked && before.selfIntersections == 0 && before.foldedEdges == 0)
      << before.summary();
    ASSERT_EQ(before.boundaryEdges, trial % 2 == 0 ? 0u : 3u);
    TriangleMesh mesh = joined;
    std::vector<char> changed(mesh.points.size(), 0);
    auto flagCorners = [&](const Triangle& t)
    {
      for (std::int32_t v : t)
        changed[static_cast<std::size_t>(v)] = 1;
    };
    // The operations stay near one triangle, as a repair's do.
    const std::size_t centre = any(mesh.triangles.size());
    auto nearTriangle = [&]
    {
      const Triangle& c = mesh.triangles[std::min(centre, mesh.triangles.size() - 1)];
      const std::int32_t v = c[any(3)];
      std::vector<std::size_t> around;
      for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        if (std::count(mesh.triangles[f].begin(), mesh.triangles[f].end(), v) > 0)
          around.push_back(f);
      return around.empty() ? std::min(centre, mesh.triangles.size() - 1) : around[any(around.size())];
    };
    for (int op = 0; op < 1 + trial / 2 % 4; ++op)
    {
      const std::size_t f = nearTriangle();
      const Triangle t = mesh.triangles[f];
      const std::size_t kind = any(7);
      switch (kind)
      {
        case 0: // the flip of edge t[0] t[1], wherever that leaves the edge between the far corners
        {
          for (std::size_t g = 0; g < mesh.triangles.size(); ++g)
          {
            const Triangle u = mesh.triangles[g];
            for (int i = 0; i < 3 && g != f; ++i)
              if (u[i] == t[1] && u[(i + 1) % 3] == t[0])
              {
                const std::int32_t a = t[0], b = t[1], c = t[2], d = u[(i + 2) % 3];
                flagCorners(t);
                flagCorners(u);
                mesh.triangles[f] = { a, d, c };
                mesh.triangles[g] = { b, c, d };
                g = mesh.triangles.size() - 1;
                break;
              }
          }
          break;
        }
        case 1: // the collapse of edge t[0] t[1] onto t[0], wherever its link says no
        case 5: // or t[0] glued to a vertex elsewhere on the mesh: a pinch (two fans at one vertex)
        {
          const std::int32_t keep = t[0];
          std::int32_t gone = t[1];
          if (kind == 5)
            if (const std::int32_t far = mesh.triangles[any(mesh.triangles.size())][0]; far != keep)
              gone = far;
          std::vector<Triangle> kept;
          for (const Triangle& u : mesh.triangles)
          {
            if (std::count(u.begin(), u.end(), gone) == 0)
            {
              kept.push_back(u);
              continue;
            }
            flagCorners(u);
            Triangle w = u;
            for (std::int32_t& corner : w)
              corner = corner == gone ? keep : corner;
            flagCorners(w); // the triangle as it is now, `keep` among its corners
            if (std::count(w.begin(), w.end(), keep) == 1)
              kept.push_back(w);
          }
          mesh.triangles = kept;
          break;
        }
        case 2: // a corner moved by up to an edge: folds, crossings or nothing
        {
          const auto v = static_cast<std::size_t>(t[any(3)]);
          for (const Triangle& u : mesh.triangles)
            if (std::count(u.begin(), u.end(), static_cast<std::int32_t>(v)) > 0)
              flagCorners(u);
          std::uniform_real_distribution<double> reach(-1.5, 1.5);
          mesh.points[v] = { mesh.points[v].x + reach(random), mesh.points[v].y + reach(random), mesh.points[v].z + reach(random) };
          break;
        }
        case 6: // a corner moved onto the next one: triangles without area
        {
          const auto v = static_cast<std::size_t>(t[0]);
          for (const Triangle& u : mesh.triangles)
            if (std::count(u.begin(), u.end(), t[0]) > 0)
              flagCorners(u);
          mesh.points[v] = mesh.points[static_cast<std::size_t>(t[1])];
          break;
        }
        case 3: // a hole
          flagCorners(t);
          mesh.triangles.erase(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(f));
          break;
        default: // a fin: the triangle twice
          flagCorners(t);
          mesh.triangles.push_back(t);
      }
    }
    // Unused vertices dropped, the rest renumbered in order, as a repair leaves its mesh.
    std::vector<std::int32_t> index(mesh.points.size(), -1);
    for (const Triangle& u : mesh.triangles)
      for (std::int32_t v : u)
        index[static_cast<std::size_t>(v)] = 0;
    TriangleMesh renumbered;
    std::vector<char> renumberedChanged;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      if (index[v] == 0)
      {
        index[v] = static_cast<std::int32_t>(renumbered.points.size());
        renumbered.points.push_back(mesh.points[v]);
        renumberedChanged.push_back(changed[v]);
      }
    for (const Triangle& u : mesh.triangles)
      renumbered.triangles.push_back({ index[u[0]], index[u[1]], index[u[2]] });
    std::vector<std::pair<std::size_t, std::size_t>> local, whole;
    const MeshValidation wholeValidation = validateMesh(renumbered, whole);
    expectSameValidation(validateMeshAfterLocalChange(renumbered, before, renumberedChanged, local), wholeValidation,
                         "trial " + std::to_string(trial));
    EXPECT_EQ(local, whole) << "trial " << trial;
    const std::size_t kinds[7] = { wholeValidation.boundaryEdges, wholeValidation.nonManifoldEdges,
                                   wholeValidation.nonManifoldVertices, wholeValidation.foldedEdges,
                                   wholeValidation.selfIntersections, wholeValidation.degenerateTriangles,
                                   wholeValidation.valid() ? 1u : 0u };
    for (int k = 0; k < 7; ++k)
      seen[k] += kinds[k];
  }
  // Holes, fins, pinched fans, folds, crossings, triangles without area, and valid changes were met.
  for (int k = 0; k < 7; ++k)
    EXPECT_GT(seen[k], 0u) << "kind " << k;
}

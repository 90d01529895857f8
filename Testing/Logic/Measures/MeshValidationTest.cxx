#include "ContourStacks.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace slicemesh;

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

void expectSameValidation(const MeshValidation& a, const MeshValidation& b, const std::string& where)
{
  EXPECT_EQ(a.vertices, b.vertices) << where;
  EXPECT_EQ(a.triangles, b.triangles) << where;
  EXPECT_EQ(a.degenerateTriangles, b.degenerateTriangles) << where;
  EXPECT_EQ(a.boundaryEdges, b.boundaryEdges) << where;
  EXPECT_EQ(a.nonManifoldEdges, b.nonManifoldEdges) << where;
  EXPECT_EQ(a.nonManifoldVertices, b.nonManifoldVertices) << where;
  EXPECT_EQ(a.inconsistentEdges, b.inconsistentEdges) << where;
  EXPECT_EQ(a.misorientedComponents, b.misorientedComponents) << where;
  EXPECT_EQ(a.foldedEdges, b.foldedEdges) << where;
  EXPECT_EQ(a.selfIntersections, b.selfIntersections) << where;
  EXPECT_EQ(a.selfIntersectionChecked, b.selfIntersectionChecked) << where;
  EXPECT_EQ(a.components, b.components) << where;
  EXPECT_EQ(a.eulerCharacteristic, b.eulerCharacteristic) << where;
  EXPECT_EQ(a.area, b.area) << where; // bit for bit: the same sums in the same order
  EXPECT_EQ(a.volume, b.volume) << where;
  EXPECT_EQ(a.minAngleDegrees, b.minAngleDegrees) << where;
  EXPECT_EQ(a.fractionAnglesBelow30, b.fractionAnglesBelow30) << where;
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

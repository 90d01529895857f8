#include "Measures/MeshValidation.h"

#include <gtest/gtest.h>

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

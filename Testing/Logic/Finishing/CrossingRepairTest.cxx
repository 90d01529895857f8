// The local repair of a surface's crossings, on closed surfaces whose answer is known: a fold made
// on a flat face, which a collapse, or a move of its vertex, undoes without moving the face; and two
// boxes through each other, which no flip, collapse or move parts. And on a real remesh's fold that
// takes two operations in a row. And the widening of a finished piece's narrow triangles, made of
// the same operations.
#include "SameValidation.h"

#include "Finishing/CrossingPlaces.h"
#include "Finishing/CrossingRepair.h"
#include "Finishing/NarrowTriangleWidening.h"
#include "Measures/MeshValidation.h"
#include "Measures/SelfIntersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

using namespace slicemesh;

namespace
{

/** The surface of the box [origin, origin + n] (mm), each face an n x n grid of unit squares split
 *  along one diagonal, facing outwards. */
TriangleMesh gridBox(int n, const Point3& origin = { 0.0, 0.0, 0.0 })
{
  TriangleMesh mesh;
  std::map<std::array<int, 3>, std::int32_t> index;
  const auto vertex = [&](const std::array<int, 3>& c)
  {
    const auto [at, added] = index.emplace(c, static_cast<std::int32_t>(mesh.points.size()));
    if (added)
      mesh.points.push_back({ origin.x + c[0], origin.y + c[1], origin.z + c[2] });
    return at->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= n; side += n)
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          const auto at = [&](int a, int b)
          {
            std::array<int, 3> c{};
            c[axis] = side;
            c[u] = a;
            c[v] = b;
            return vertex(c);
          };
          const std::int32_t p = at(i, j), q = at(i + 1, j), r = at(i + 1, j + 1), s = at(i, j + 1);
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
          if (side == n)
          {
            mesh.triangles.push_back({ p, q, r });
            mesh.triangles.push_back({ p, r, s });
          }
          else
          {
            mesh.triangles.push_back({ p, r, q });
            mesh.triangles.push_back({ p, s, r });
          }
        }
    }
  return mesh;
}

std::int32_t vertexAt(const TriangleMesh& mesh, const Point3& p)
{
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (mesh.points[v].x == p.x && mesh.points[v].y == p.y && mesh.points[v].z == p.z)
      return static_cast<std::int32_t>(v);
  return -1;
}

/** The vertices (v x y z) and triangles (f a b c, numbered from 1) of a Wavefront OBJ file. (The
 *  project's mesh reader is VTK's, in the Mesh module; the Logic suite links the Logic library only.) */
TriangleMesh readObj(const std::string& path)
{
  TriangleMesh mesh;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "v")
    {
      Point3 p{};
      fields >> p.x >> p.y >> p.z;
      mesh.points.push_back(p);
    }
    else if (kind == "f")
    {
      Triangle t{};
      for (std::int32_t& corner : t)
      {
        fields >> corner;
        --corner;
      }
      mesh.triangles.push_back(t);
    }
  }
  return mesh;
}

/** What the finishing relies on to validate only the changed part of a repaired piece: every
 *  triangle of `repaired` that `before` did not have (by the corners' former numbers and points) has
 *  a movable corner and all its corners flagged in `repair.changed`, and every corner still in the
 *  mesh of each triangle of `before` that `repaired` no longer has is flagged. */
void expectTheChangeFlagged(const TriangleMesh& before, const TriangleMesh& repaired, const CrossingRepair& repair,
                            const std::vector<char>& movable)
{
  ASSERT_EQ(repair.changed.size(), repaired.points.size());
  const auto canonical = [](Triangle t)
  {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::set<Triangle> had, kept;
  for (const Triangle& t : before.triangles)
    had.insert(canonical(t));
  // Each former vertex's number now, where it kept its point (a moved vertex's new point is not it).
  std::map<std::int32_t, std::int32_t> nowOf;
  for (std::size_t v = 0; v < repaired.points.size(); ++v)
  {
    const Point3 &now = repaired.points[v], &was = before.points[static_cast<std::size_t>(repair.formerVertex[v])];
    if (now.x == was.x && now.y == was.y && now.z == was.z)
      nowOf[repair.formerVertex[v]] = static_cast<std::int32_t>(v);
  }
  std::size_t changed = 0;
  for (const Triangle& t : repaired.triangles)
  {
    Triangle former{};
    bool moved = false;
    for (int i = 0; i < 3; ++i)
    {
      former[i] = repair.formerVertex[static_cast<std::size_t>(t[i])];
      moved = moved || !nowOf.count(former[i]) || nowOf.at(former[i]) != t[i];
    }
    if (!moved && had.count(canonical(former)))
    {
      kept.insert(canonical(former));
      continue;
    }
    ++changed;
    EXPECT_TRUE(movable[static_cast<std::size_t>(former[0])] || movable[static_cast<std::size_t>(former[1])] ||
                movable[static_cast<std::size_t>(former[2])]);
    for (std::int32_t v : t)
      EXPECT_TRUE(repair.changed[static_cast<std::size_t>(v)]) << "a corner of a new triangle, vertex " << v;
  }
  EXPECT_GT(changed, 0u);
  for (const Triangle& t : before.triangles)
    if (!kept.count(canonical(t)))
      for (std::int32_t v : t)
        if (nowOf.count(v))
          EXPECT_TRUE(repair.changed[static_cast<std::size_t>(nowOf.at(v))]) << "a corner of a removed triangle, vertex " << v;
}

/** After a repair that undid every crossing of `before` (its validation: `validation`), the
 *  validation around the changed triangles is the whole one, field by field. */
void expectTheLocalValidationWhole(const TriangleMesh& repaired, const MeshValidation& validation,
                                   const CrossingRepair& repair)
{
  MeshValidation leftAlone = validation; // every crossing had a triangle the repair changed
  leftAlone.selfIntersections = 0;
  std::vector<std::pair<std::size_t, std::size_t>> local, whole;
  const MeshValidation around = validateMeshAfterLocalChange(repaired, leftAlone, repair.changed, local);
  const MeshValidation all = validateMesh(repaired, whole);
  slicemesh::testing::expectSameValidation(around, all, "repaired");
  EXPECT_EQ(local, whole);
}

} // namespace

TEST(CrossingRepair, AFoldOnAFlatFaceIsCollapsedAwayAndTheFaceStaysFlat)
{
  const TriangleMesh original = gridBox(8);
  TriangleMesh box = original;
  const MeshValidation before = validateMesh(box);
  ASSERT_TRUE(before.valid()) << before.summary();
  // A vertex of the top face pushed past its diagonal neighbour: its triangles fold over their
  // neighbours, in the face's plane, as a remesh's vertex can where two voxels touch along an edge.
  const std::int32_t pushed = vertexAt(box, { 4.0, 4.0, 8.0 });
  ASSERT_GE(pushed, 0);
  box.points[static_cast<std::size_t>(pushed)] = { 5.6, 5.6, 8.0 };
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  const MeshValidation folded = validateMesh(box, crossings);
  ASSERT_GT(folded.selfIntersections, 0u) << folded.summary();

  std::vector<char> movable(box.points.size(), 0);
  for (std::size_t v = 0; v < box.points.size(); ++v)
    movable[v] = box.points[v].z == 8.0 && std::abs(box.points[v].x - 4.5) < 3.0 && std::abs(box.points[v].y - 4.5) < 3.0;
  const TriangleMesh folding = box;
  const CrossingRepair repair = repairCrossingsLocally(box, crossings, movable, 1.1);

  const MeshValidation after = validateMesh(box);
  EXPECT_TRUE(after.valid()) << after.summary();
  EXPECT_EQ(after.selfIntersections, 0u);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  EXPECT_EQ(after.components, 1u);
  EXPECT_GE(repair.collapses, 1u);
  expectTheChangeFlagged(folding, box, repair, movable);
  expectTheLocalValidationWhole(box, folded, repair);
  // No point moved: the box is the same solid (the top face flat at z = 8).
  EXPECT_NEAR(after.volume, 512.0, 1e-9);
  EXPECT_EQ(box.points.size(), before.vertices - repair.collapses);
  ASSERT_EQ(repair.formerVertex.size(), box.points.size());
  for (std::size_t v = 0; v < box.points.size(); ++v)
  {
    const Point3& was = original.points[static_cast<std::size_t>(repair.formerVertex[v])];
    if (repair.formerVertex[v] != pushed)
      EXPECT_TRUE(box.points[v].x == was.x && box.points[v].y == was.y && box.points[v].z == was.z) << v;
  }
}

TEST(CrossingRepair, TwoBoxesThroughEachOtherStillCrossAndKeepTheirShape)
{
  // Crossings that are no fold: two solids through each other. Collapses can make fewer pairs of
  // (larger) triangles cross, but none parts them; each operation is bounded, so the boxes keep
  // their volume to within what the operations were allowed, and stay closed manifolds.
  TriangleMesh boxes = gridBox(4);
  const TriangleMesh other = gridBox(4, { 2.0, 2.0, 2.0 });
  const auto offset = static_cast<std::int32_t>(boxes.points.size());
  boxes.points.insert(boxes.points.end(), other.points.begin(), other.points.end());
  for (Triangle t : other.triangles)
    boxes.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  const MeshValidation before = validateMesh(boxes, crossings);
  ASSERT_GT(before.selfIntersections, 0u);
  const double edge = 1.1;

  const CrossingRepair repair = repairCrossingsLocally(boxes, crossings, std::vector<char>(boxes.points.size(), 1), edge);

  const MeshValidation after = validateMesh(boxes);
  EXPECT_GT(after.selfIntersections, 0u);
  EXPECT_TRUE(after.soundTopology()) << after.summary();
  EXPECT_EQ(after.components, 2u);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  const double operations = static_cast<double>(repair.operations());
  EXPECT_LE(std::abs(after.volume - before.volume), operations * 0.125 * edge * edge * edge + 1e-9);
}

TEST(CrossingRepair, AFoldWhoseEdgesMayNotChangeIsUndoneByMovingItsVertex)
{
  // The same fold with only the pushed vertex movable: no edge may be flipped or collapsed (both
  // ends must be movable), so the vertex itself goes to the mean of its neighbours, back into the
  // face, where its fan no longer folds.
  TriangleMesh box = gridBox(8);
  const MeshValidation before = validateMesh(box);
  const std::int32_t pushed = vertexAt(box, { 4.0, 4.0, 8.0 });
  ASSERT_GE(pushed, 0);
  box.points[static_cast<std::size_t>(pushed)] = { 5.4, 5.4, 8.0 }; // within two edges of the mean
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  const MeshValidation folded = validateMesh(box, crossings);
  ASSERT_GT(folded.selfIntersections, 0u);
  std::vector<char> movable(box.points.size(), 0);
  movable[static_cast<std::size_t>(pushed)] = 1;
  const TriangleMesh folding = box;

  const CrossingRepair repair = repairCrossingsLocally(box, crossings, movable, 1.1);

  EXPECT_TRUE(repair.undone);
  expectTheChangeFlagged(folding, box, repair, movable);
  expectTheLocalValidationWhole(box, folded, repair);
  EXPECT_EQ(repair.flips + repair.collapses, 0u);
  EXPECT_GE(repair.moves, 1u);
  const MeshValidation after = validateMesh(box);
  EXPECT_TRUE(after.valid()) << after.summary();
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  EXPECT_EQ(box.points.size(), before.vertices);
  EXPECT_NEAR(after.volume, 512.0, 1e-9);
  for (std::size_t v = 0; v < box.points.size(); ++v)
    if (repair.formerVertex[v] == pushed) // at the mean of its six neighbours: where it was
    {
      EXPECT_NEAR(box.points[v].x, 4.0, 1e-12);
      EXPECT_NEAR(box.points[v].y, 4.0, 1e-12);
      EXPECT_EQ(box.points[v].z, 8.0);
    }
}

TEST(CrossingRepair, ARemeshFoldThatNoSingleOperationImprovesIsUndoneInTwo)
{
  // The triangles within 2.5 mm of a fold of the Colin27 T1's remeshed, smoothed surface, as the
  // repair got them (Testing/Data/README.md): four crossing pairs where a voxel edge pinches two
  // sheets. Every single flip, collapse or move there leaves as many crossings; a flip followed by
  // a collapse or a move undoes them.
  TriangleMesh patch = readObj(SLICEMESH_TEST_DATA_DIR "/colin27-remesh-fold.obj");
  ASSERT_EQ(patch.triangles.size(), 153u);
  const double edge = 0.55; // the remesh's target edge on that grid (mm)
  const MeshValidation before = validateMesh(patch);
  const std::vector<std::pair<std::size_t, std::size_t>> crossings = selfIntersectingTrianglePairs(patch);
  ASSERT_GT(crossings.size(), 0u);
  // Movable as the finishing makes them: within two target edges of a crossing triangle's centroid.
  const std::vector<char> movable = verticesNear(patch, crossingPlaces(patch, crossings), 2.0 * edge);
  const std::vector<Point3> pointsBefore = patch.points;
  // For two patches of the same rim, the difference of their signed volumes (tetrahedra from the
  // origin) is the volume between them.
  const double volumeBefore = signedVolume(patch);

  const TriangleMesh folded = patch;
  const CrossingRepair repair = repairCrossingsLocally(patch, crossings, movable, edge);

  EXPECT_TRUE(repair.undone);
  expectTheChangeFlagged(folded, patch, repair, movable);
  expectTheLocalValidationWhole(patch, before, repair); // an open patch: its edges gathered whole
  EXPECT_TRUE(selfIntersectingTrianglePairs(patch).empty());
  const MeshValidation after = validateMesh(patch);
  EXPECT_EQ(after.boundaryEdges, before.boundaryEdges); // the patch's rim, untouched
  EXPECT_EQ(after.nonManifoldEdges, 0u);
  EXPECT_EQ(after.nonManifoldVertices, 0u);
  EXPECT_EQ(after.degenerateTriangles, 0u);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  // Only movable vertices moved, none farther than two edges; the volume between the patches
  // within the bound of each operation.
  for (std::size_t v = 0; v < patch.points.size(); ++v)
  {
    const auto former = static_cast<std::size_t>(repair.formerVertex[v]);
    const Point3 &p = patch.points[v], &q = pointsBefore[former];
    const double moved = std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z));
    if (!movable[former])
      EXPECT_EQ(moved, 0.0) << "vertex " << former;
    EXPECT_LE(moved, 2.0 * edge);
  }
  EXPECT_LE(std::abs(signedVolume(patch) - volumeBefore),
            static_cast<double>(repair.operations()) * 0.125 * edge * edge * edge);
}

// A finished piece's narrow triangles widened where they are (NarrowTriangleWidening): on a box whose
// face has one vertex pushed most of the way to its neighbour, the needles and caps around it are
// flipped or collapsed away; no point moves, so the face stays flat; vertices held fixed stay.
TEST(NarrowTriangleWidening, TheNeedlesAroundAPushedVertexAreTakenAwayAndTheFaceStaysFlat)
{
  TriangleMesh box = gridBox(4);
  const std::int32_t pushed = vertexAt(box, { 2.0, 2.0, 0.0 });
  ASSERT_GE(pushed, 0);
  box.points[static_cast<std::size_t>(pushed)] = { 2.8, 2.05, 0.0 };
  MeshValidation before = validateMesh(box);
  ASSERT_TRUE(before.valid()) << before.summary();
  ASSERT_GT(before.fractionAnglesBelow30, 0.0);

  // Every vertex fixed: nothing to do.
  TriangleMesh held = box;
  MeshValidation heldValidation = before;
  EXPECT_EQ(widenNarrowTriangles(held, heldValidation, std::vector<char>(box.points.size(), 1), 1.0), 0u);
  EXPECT_EQ(held.triangles, box.triangles);

  TriangleMesh widened = box;
  MeshValidation after = before;
  const std::size_t operations = widenNarrowTriangles(widened, after, {}, 1.0);
  std::printf("%zu operations; under 30 degrees %.1f%% -> %.1f%% of the triangles\n", operations,
              100.0 * before.fractionAnglesBelow30, 100.0 * after.fractionAnglesBelow30);
  EXPECT_GT(operations, 0u);
  EXPECT_TRUE(after.valid()) << after.summary();
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  EXPECT_LT(after.fractionAnglesBelow30, 0.5 * before.fractionAnglesBelow30);
  // The validation handed back is the mesh's own, field by field (its edges gathered only where the
  // widening changed triangles).
  const MeshValidation again = validateMesh(widened);
  EXPECT_EQ(again.selfIntersections, 0u);
  slicemesh::testing::expectSameValidation(after, again, "widened");
  // The widening's own record of what it changed, on which that validation relies.
  TriangleMesh locally = box;
  const std::vector<char> everyVertex(box.points.size(), 1);
  const CrossingRepair widening = widenNarrowTrianglesLocally(locally, everyVertex, 1.0, 30.0);
  EXPECT_GT(widening.operations(), 0u);
  expectTheChangeFlagged(box, locally, widening, everyVertex);
  // Collapses and flips move no point: every vertex is one of the box's, the pushed one included.
  for (const Point3& p : widened.points)
    EXPECT_NE(vertexAt(box, p), -1);
  EXPECT_NEAR(after.volume, before.volume, 1e-9);

  // Without narrow triangles, nothing is done.
  TriangleMesh plain = gridBox(4);
  MeshValidation plainValidation = validateMesh(plain);
  EXPECT_EQ(widenNarrowTriangles(plain, plainValidation, {}, 1.0), 0u);
}

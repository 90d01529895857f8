// selfIntersectingTrianglePairs: each way two triangles of one mesh can meet, and the grid that
// finds the pairs to test (long triangles across many cells, far-apart pieces); the test again after
// some vertices moved, against the whole one.
#include "Measures/SelfIntersections.h"

#include "Core/BoundingBox.h"

#include <algorithm>

#include <gtest/gtest.h>

using namespace slicemesh;

namespace
{

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

TriangleMesh tetrahedron(double x = 0.0)
{
  TriangleMesh mesh;
  mesh.points = { { x, 0, 0 }, { x + 1, 0, 0 }, { x, 1, 0 }, { x, 0, 1 } };
  mesh.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } };
  return mesh;
}

/** a and b as one mesh (b's vertices after a's). */
TriangleMesh joined(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh mesh = a;
  const auto offset = static_cast<std::int32_t>(a.points.size());
  mesh.points.insert(mesh.points.end(), b.points.begin(), b.points.end());
  for (const Triangle& t : b.triangles)
    mesh.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  return mesh;
}

/** Numbers spread evenly over [low, high), the same sequence on every platform. */
class Uniform
{
public:
  double operator()(double low, double high)
  {
    m_State = m_State * 6364136223846793005ull + 1442695040888963407ull;
    return low + (high - low) * static_cast<double>(m_State >> 11) / static_cast<double>(1ull << 53);
  }

private:
  std::uint64_t m_State = 12345;
};

/** `count` unit tetrahedra at random places in a cube of side `side`, many through each other. */
TriangleMesh scatteredTetrahedra(int count, double side, Uniform& uniform)
{
  TriangleMesh mesh;
  for (int i = 0; i < count; ++i)
  {
    const TriangleMesh one = tetrahedron();
    const Point3 at{ uniform(0, side), uniform(0, side), uniform(0, side) };
    const auto offset = static_cast<std::int32_t>(mesh.points.size());
    for (const Point3& p : one.points)
      mesh.points.push_back({ p.x + at.x, p.y + at.y, p.z + at.z });
    for (const Triangle& t : one.triangles)
      mesh.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return mesh;
}

/** A row of 200 small triangles across the x axis (at x = 0.5, 1.5, ...) and one sliver along it,
 *  `y` off the axis: at y = 0 it passes through every small triangle. */
TriangleMesh rowAndSliver(double y)
{
  TriangleMesh mesh;
  for (int i = 0; i < 200; ++i)
  {
    const auto first = static_cast<std::int32_t>(mesh.points.size());
    mesh.points.push_back({ i + 0.5, -0.5, -0.5 });
    mesh.points.push_back({ i + 0.5, 0.5, -0.5 });
    mesh.points.push_back({ i + 0.5, 0.0, 0.5 });
    mesh.triangles.push_back({ first, first + 1, first + 2 });
  }
  const auto first = static_cast<std::int32_t>(mesh.points.size());
  mesh.points.push_back({ -1.0, y, 0.0 });
  mesh.points.push_back({ 201.0, y, 0.0 });
  mesh.points.push_back({ 201.0, y, 0.01 });
  mesh.triangles.push_back({ first, first + 1, first + 2 });
  return mesh;
}

} // namespace

TEST(SelfIntersections, AClosedConvexMeshHasNone)
{
  EXPECT_TRUE(selfIntersectingTrianglePairs(tetrahedron()).empty());
  // Two apart: nothing either, whatever the grid makes of the empty space between them.
  EXPECT_TRUE(selfIntersectingTrianglePairs(joined(tetrahedron(), tetrahedron(50.0))).empty());
}

TEST(SelfIntersections, TrianglesFoldedOntoEachOtherAcrossTheirEdgeCross)
{
  // Triangles 0 and 1 share edge 0-1; the corner of triangle 1 lies in triangle 0's plane, on its side.
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 2, 0, 0 }, { 1, 1, 0 }, { 1, 0.5, 0 } };
  mesh.triangles = { { 0, 1, 2 }, { 1, 0, 3 } };
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh), (Pairs{ { 0, 1 } }));
  mesh.points[3] = { 1, -0.5, 0 }; // the other side: a flat pair, no fold
  EXPECT_TRUE(selfIntersectingTrianglePairs(mesh).empty());
  mesh.points[3] = { 1, 0.5, 1e-9 }; // out of the plane, however little: they meet along the edge only
  EXPECT_TRUE(selfIntersectingTrianglePairs(mesh).empty());
}

TEST(SelfIntersections, TrianglesWithACommonCornerCrossWhereAnEdgePiercesTheOther)
{
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 2, -1, 0 }, { 2, 1, 0 }, { 1, 0, -1 }, { 1, 0, 1 } };
  mesh.triangles = { { 0, 1, 2 }, { 0, 3, 4 } }; // the second's edge 3-4 passes through the first
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh), (Pairs{ { 0, 1 } }));
  mesh.points[3] = { 1, 0, 0.5 }; // lifted above: they meet at the corner only
  EXPECT_TRUE(selfIntersectingTrianglePairs(mesh).empty());
  mesh.points[3] = { 1, 0, -0.5 }; // both other corners below the first's plane: the corner only
  mesh.points[4] = { 1, 0.5, -1e-9 };
  EXPECT_TRUE(selfIntersectingTrianglePairs(mesh).empty());
  // One other corner in the first's plane, inside it: they share a segment from the common corner.
  mesh.points[3] = { 1, 0, 0 };
  mesh.points[4] = { 1, 0, 1 };
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh), (Pairs{ { 0, 1 } }));
  // Both in its plane, the second triangle inside the first.
  mesh.points[3] = { 1, -0.2, 0 };
  mesh.points[4] = { 1, 0.2, 0 };
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh), (Pairs{ { 0, 1 } }));
  // Both in its plane, the second beside the first (across the common corner): the corner only.
  mesh.points[3] = { -1, -0.2, 0 };
  mesh.points[4] = { -1, 0.2, 0 };
  EXPECT_TRUE(selfIntersectingTrianglePairs(mesh).empty());
}

TEST(SelfIntersections, SeparateTrianglesThatTouchCross)
{
  // A corner of the second tetrahedron on a face of the first: touching is crossing for a surface.
  TriangleMesh second = tetrahedron();
  for (Point3& p : second.points)
    p = { p.x + 0.2, p.y + 0.2, p.z - 1.0 }; // its top corner (0.2, 0.2, 0) on the first's base
  const Pairs pairs = selfIntersectingTrianglePairs(joined(tetrahedron(), second));
  ASSERT_FALSE(pairs.empty());
  for (const auto& [a, b] : pairs)
  {
    EXPECT_EQ(a, 0u) << "only the first's base is touched";
    EXPECT_GE(b, 4u);
  }
}

TEST(SelfIntersections, ADegenerateTriangleIsReportedWithItself)
{
  TriangleMesh mesh = tetrahedron();
  mesh.points.push_back({ 5, 5, 5 });
  mesh.points.push_back({ 6, 6, 6 });
  mesh.points.push_back({ 7, 7, 7 });
  mesh.triangles.push_back({ 4, 5, 6 });
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh), (Pairs{ { 4, 4 } }));
}

TEST(SelfIntersections, ALongTriangleIsTestedAgainstEverySmallOneItPasses)
{
  // A row of 200 small triangles and one sliver through all of them: the sliver covers many cells
  // of a grid sized for the small ones, and crosses each once.
  const TriangleMesh mesh = rowAndSliver(0.0);
  const Pairs pairs = selfIntersectingTrianglePairs(mesh);
  ASSERT_EQ(pairs.size(), 200u);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    EXPECT_EQ(pairs[i], (std::pair<std::size_t, std::size_t>{ i, 200 }));
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh, 1), pairs);
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh, 8), pairs);
}

TEST(SelfIntersections, AfterMovingSomeVerticesTheSamePairsAsTheWholeTest)
{
  // 300 small tetrahedra scattered in a box, many of them through each other; rounds of moving a
  // few vertices (some onto a line with two others: degenerate triangles, some by several sizes of
  // a tetrahedron: new crossings far away) and, every fifth round, a quarter of them (the whole test
  // then). Each round's pairs from the last round's must be the whole test's.
  Uniform uniform;
  TriangleMesh mesh = scatteredTetrahedra(300, 10.0, uniform);
  Pairs before = selfIntersectingTrianglePairs(mesh);
  ASSERT_GT(before.size(), 10u); // the test means something only if some cross
  std::size_t degenerateSeen = 0;
  for (int round = 0; round < 20; ++round)
  {
    std::vector<char> moved(mesh.points.size(), 0);
    const double share = round % 5 == 4 ? 0.25 : 0.02;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
    {
      if (uniform(0, 1) >= share)
        continue;
      moved[v] = 1;
      if (v % 4 == 0 && uniform(0, 1) < 0.3) // onto the middle of its tetrahedron's edge 1-2
      {
        const Point3& a = mesh.points[v + 1];
        const Point3& b = mesh.points[v + 2];
        mesh.points[v] = { (a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2 };
      }
      else
      {
        const double reach = uniform(0, 1) < 0.5 ? 0.3 : 4.0;
        mesh.points[v] = { mesh.points[v].x + uniform(-reach, reach), mesh.points[v].y + uniform(-reach, reach),
                           mesh.points[v].z + uniform(-reach, reach) };
      }
    }
    const Pairs whole = selfIntersectingTrianglePairs(mesh);
    const Pairs updated = selfIntersectingTrianglePairsAfterMoving(mesh, before, moved);
    ASSERT_EQ(updated, whole) << "round " << round;
    EXPECT_EQ(selfIntersectingTrianglePairsAfterMoving(mesh, before, moved, 1), whole);
    EXPECT_EQ(selfIntersectingTrianglePairsAfterMoving(mesh, before, moved, 8), whole);
    for (const auto& pair : whole)
      degenerateSeen += pair.first == pair.second;
    before = updated;
  }
  EXPECT_GT(degenerateSeen, 0u);
}

TEST(SelfIntersections, AfterMovingALongTriangleEverySmallOneItNowPassesIsFound)
{
  // The row of small triangles of the test above with the sliver beside it, then moved through it.
  TriangleMesh mesh = rowAndSliver(3.0);
  const Pairs before = selfIntersectingTrianglePairs(mesh);
  ASSERT_TRUE(before.empty());
  std::vector<char> moved(mesh.points.size(), 0);
  for (std::size_t v = mesh.points.size() - 3; v < mesh.points.size(); ++v)
  {
    mesh.points[v].y = 0.0;
    moved[v] = 1;
  }
  const Pairs after = selfIntersectingTrianglePairsAfterMoving(mesh, before, moved);
  EXPECT_EQ(after.size(), 200u);
  EXPECT_EQ(after, selfIntersectingTrianglePairs(mesh));
}

TEST(SelfIntersections, CellsFiledAGroupAtATimeGiveTheSamePairs)
{
  // Tetrahedra through each other (more triangles than one range of the filing: 16,384) and a sliver
  // through a row of small triangles (a box in 200 cells): the pairs of every pair of triangles
  // whose boxes meet, tested one by one, whatever the group size (50: about a group per run of
  // cells) and the number of threads.
  Uniform uniform;
  const TriangleMesh mesh = joined(scatteredTetrahedra(4300, 30.0, uniform), rowAndSliver(0.0));
  ASSERT_GT(mesh.triangles.size(), 16384u);
  std::vector<std::pair<BoundingBox, std::size_t>> byLowX;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    byLowX.emplace_back(boxOfTriangle(mesh, t), t);
  std::sort(byLowX.begin(), byLowX.end(), [](const auto& a, const auto& b) { return a.first.low[0] < b.first.low[0]; });
  Pairs oneByOne;
  for (std::size_t i = 0; i < byLowX.size(); ++i)
    for (std::size_t j = i + 1; j < byLowX.size() && byLowX[j].first.low[0] <= byLowX[i].first.high[0]; ++j)
    {
      const std::size_t s = byLowX[i].second, t = byLowX[j].second;
      if (byLowX[i].first.overlaps(byLowX[j].first) && trianglesCross(mesh.points, mesh.triangles[s], mesh.triangles[t]))
        oneByOne.emplace_back(std::min(s, t), std::max(s, t));
    }
  std::sort(oneByOne.begin(), oneByOne.end());
  ASSERT_GT(oneByOne.size(), 400u); // the tetrahedra's crossings and the sliver's 200
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh, 2), oneByOne);
  for (std::size_t perGroup : { 50, 5000, 40000 })
    for (unsigned int threads : { 1u, 3u })
      EXPECT_EQ(selfIntersectingTrianglePairsInGroups(mesh, perGroup, threads), oneByOne)
        << perGroup << " filings a group, " << threads << " threads";
}

// crossingTriangles: which of several closed meshes (no shared vertices) cross
// each other, and along which pairs of triangles.
#include "ContourStacks.h"
#include "Measures/MeshCrossings.h"
#include "Tiling/SurfaceReconstruction.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace slicemesh::testing
{
namespace
{

/** A closed ball of radius 6 mm about (cx, 0, 0), sliced every 1.5 mm. */
TriangleMesh ball(double cx)
{
  return reconstructSurface(ballStack(cx, 0.0, 0.0, 6.0, 48, 1.5));
}

/** The pairs of meshes the pairs of triangles belong to, each once, in increasing order. */
std::vector<std::pair<std::size_t, std::size_t>> meshPairs(const std::vector<TrianglePair>& pairs)
{
  std::vector<std::pair<std::size_t, std::size_t>> meshes;
  for (const auto& [a, b] : pairs)
    meshes.emplace_back(a.mesh, b.mesh);
  std::sort(meshes.begin(), meshes.end());
  meshes.erase(std::unique(meshes.begin(), meshes.end()), meshes.end());
  return meshes;
}

TEST(MeshCrossings, OnlyMeshesThatMeetAreNamed)
{
  const TriangleMesh a = ball(0.0), apart = ball(40.0), overlapping = ball(8.0), far = ball(60.0);
  // Apart (boxes do not even overlap): nothing.
  EXPECT_TRUE(crossingTriangles({ &a, &apart }).empty());
  // Two balls 8 mm apart overlap: their surfaces cross along a circle, and only that pair is named.
  const auto pairs = crossingTriangles({ &a, &apart, &overlapping, &far });
  const auto crossing = meshPairs(pairs);
  ASSERT_EQ(crossing.size(), 1u);
  EXPECT_EQ(crossing[0], (std::pair<std::size_t, std::size_t>{ 0, 2 }));
  EXPECT_GT(pairs.size(), 10u); // many triangle pairs along the circle of contact
}

TEST(MeshCrossings, AMeshDoesNotCrossItself)
{
  const TriangleMesh a = ball(0.0);
  EXPECT_TRUE(crossingTriangles({ &a }).empty()); // its own neighbouring triangles touch, by design
}

TEST(MeshCrossings, TheCrossingTrianglePairsAreNamedInOrder)
{
  // Two balls of radius 6 mm 8 mm apart cross along the circle x = 4, of radius sqrt(20) mm.
  const TriangleMesh a = ball(0.0), apart = ball(40.0), overlapping = ball(8.0);
  const auto pairs = crossingTriangles({ &a, &apart, &overlapping });
  ASSERT_GT(pairs.size(), 10u);
  EXPECT_EQ(meshPairs(pairs), (std::vector<std::pair<std::size_t, std::size_t>>{ { 0, 2 } }));
  EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
  EXPECT_TRUE(std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end()); // each pair once
  auto centroid = [](const TriangleMesh& mesh, std::size_t t)
  {
    Point3 c{ 0.0, 0.0, 0.0 };
    for (std::int32_t v : mesh.triangles[t])
    {
      c.x += mesh.points[static_cast<std::size_t>(v)].x / 3.0;
      c.y += mesh.points[static_cast<std::size_t>(v)].y / 3.0;
      c.z += mesh.points[static_cast<std::size_t>(v)].z / 3.0;
    }
    return c;
  };
  for (const auto& [first, second] : pairs)
  {
    // The lower mesh's triangle first; the ball far apart is in none.
    EXPECT_EQ(first.mesh, 0u);
    EXPECT_EQ(second.mesh, 2u);
    ASSERT_LT(first.triangle, a.triangles.size());
    ASSERT_LT(second.triangle, overlapping.triangles.size());
    // Both triangles lie on the circle of contact, to within their own size (edges under 1.5 mm).
    for (const Point3& c : { centroid(a, first.triangle), centroid(overlapping, second.triangle) })
    {
      EXPECT_NEAR(c.x, 4.0, 1.5);
      EXPECT_NEAR(std::hypot(c.y, c.z), std::sqrt(20.0), 1.5);
    }
  }
  // Listed the other way round, the same pairs, each still with the lower mesh's triangle first.
  const auto reversed = crossingTriangles({ &overlapping, &apart, &a });
  ASSERT_EQ(reversed.size(), pairs.size());
  for (const auto& [first, second] : reversed)
  {
    EXPECT_EQ(first.mesh, 0u); // `overlapping`, now first
    EXPECT_EQ(second.mesh, 2u);
    const TrianglePair same{ { 0, second.triangle }, { 2, first.triangle } };
    EXPECT_TRUE(std::binary_search(pairs.begin(), pairs.end(), same));
  }
  EXPECT_TRUE(crossingTriangles({ &a, &apart }).empty());
  EXPECT_TRUE(crossingTriangles({ &a }).empty());
}

TEST(MeshCrossings, EveryPairOfEveryTwoMeshesOnAnyNumberOfThreads)
{
  // Five balls in a row, each overlapping the next (and one two along), one far: against every pair
  // of triangles of different meshes tested exactly, on 1, 2 and 8 threads.
  std::vector<TriangleMesh> balls;
  for (double cx : { 0.0, 5.0, 10.0, 11.5, 20.0, 80.0 })
    balls.push_back(ball(cx));
  std::vector<const TriangleMesh*> meshes;
  for (const TriangleMesh& b : balls)
    meshes.push_back(&b);
  auto triangleOf = [&](std::size_t m, std::size_t t)
  {
    auto point = [&](int corner)
    {
      const Point3& p = balls[m].points[static_cast<std::size_t>(balls[m].triangles[t][corner])];
      return CGAL::Epick::Point_3(p.x, p.y, p.z);
    };
    return CGAL::Epick::Triangle_3(point(0), point(1), point(2));
  };
  std::vector<TrianglePair> everyPair;
  for (std::size_t a = 0; a < balls.size(); ++a)
    for (std::size_t b = a + 1; b < balls.size(); ++b)
      for (std::size_t s = 0; s < balls[a].triangles.size(); ++s)
        for (std::size_t t = 0; t < balls[b].triangles.size(); ++t)
        {
          const auto ts = triangleOf(a, s), tt = triangleOf(b, t);
          if (CGAL::do_overlap(ts.bbox(), tt.bbox()) && CGAL::do_intersect(ts, tt))
            everyPair.push_back({ { a, s }, { b, t } });
        }
  std::sort(everyPair.begin(), everyPair.end());
  ASSERT_FALSE(everyPair.empty());
  // Balls of radius 6 whose centres are less than 12 apart: 0-1, 0-2, 0-3, 1-2, 1-3, 2-3, 2-4, 3-4.
  EXPECT_EQ(meshPairs(everyPair).size(), 8u);
  for (unsigned int threads : { 1u, 2u, 8u })
    EXPECT_EQ(crossingTriangles(meshes, threads), everyPair) << threads << " threads";
}

TEST(MeshCrossings, ALargePieceAmongSpecksAndABroadNeighbour)
{
  // A ball of radius 30 mm of over 65,536 triangles (searched on every thread), 60 specks of
  // radius 1-2 mm around it (crossing its surface, inside it, outside it) and a ball whose box spans
  // many of the specks' cells (tested by every triangle, not filed): the pairs are every pair of
  // triangles of different meshes that meet, each mesh's triangles filtered by the other's box alone.
  auto ballAt = [](double cx, double cy, double cz, double r, int points, double dz)
  { return reconstructSurface(ballStack(cx, cy, cz, r, points, dz)); };
  std::vector<TriangleMesh> pieces{ ballAt(0.0, 0.0, 0.0, 30.0, 360, 0.5), ballAt(0.0, 0.0, 33.0, 8.0, 48, 1.0) };
  ASSERT_GE(pieces[0].triangles.size(), 65536u);
  for (int k = 0; k < 60; ++k)
  {
    const double theta = 0.37 * k, phi = 0.1 + 0.047 * k, r = 26.0 + 0.15 * k; // 26 to 35 mm out
    pieces.push_back(ballAt(r * std::sin(phi) * std::cos(theta), r * std::sin(phi) * std::sin(theta), r * std::cos(phi),
                            1.0 + 0.015 * k, 16, 0.5));
  }
  std::vector<const TriangleMesh*> meshes;
  for (const TriangleMesh& p : pieces)
    meshes.push_back(&p);
  auto triangleOf = [&](std::size_t m, std::size_t t)
  {
    auto point = [&](int corner)
    {
      const Point3& p = pieces[m].points[static_cast<std::size_t>(pieces[m].triangles[t][corner])];
      return CGAL::Epick::Point_3(p.x, p.y, p.z);
    };
    return CGAL::Epick::Triangle_3(point(0), point(1), point(2));
  };
  std::vector<CGAL::Bbox_3> boxes(pieces.size());
  for (std::size_t m = 0; m < pieces.size(); ++m)
    for (std::size_t t = 0; t < pieces[m].triangles.size(); ++t)
      boxes[m] += triangleOf(m, t).bbox();
  auto boxOf = [&](std::size_t m) { return boxes[m]; };
  std::vector<TrianglePair> expected;
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size(); ++b)
    {
      if (!CGAL::do_overlap(boxOf(a), boxOf(b)))
        continue;
      std::vector<std::size_t> inB, inA; // a's triangles in b's box, b's in a's
      for (std::size_t s = 0; s < pieces[a].triangles.size(); ++s)
        if (CGAL::do_overlap(triangleOf(a, s).bbox(), boxOf(b)))
          inB.push_back(s);
      for (std::size_t t = 0; t < pieces[b].triangles.size(); ++t)
        if (CGAL::do_overlap(triangleOf(b, t).bbox(), boxOf(a)))
          inA.push_back(t);
      for (std::size_t s : inB)
        for (std::size_t t : inA)
          if (CGAL::do_intersect(triangleOf(a, s), triangleOf(b, t)))
            expected.push_back({ { a, s }, { b, t } });
    }
  std::sort(expected.begin(), expected.end());
  const auto crossed = meshPairs(expected);
  // Most specks near the large ball's surface cross it; the broad ball crosses it too.
  EXPECT_TRUE(std::binary_search(crossed.begin(), crossed.end(), std::pair<std::size_t, std::size_t>(0, 1)));
  EXPECT_GE(crossed.size(), 20u);
  for (unsigned int threads : { 1u, 2u })
    EXPECT_EQ(crossingTriangles(meshes, threads), expected) << threads << " threads";
}

} // namespace
TEST(MeshCrossings, TwoLargeMeshesWithinEachOthersBoxesOnAnyNumberOfThreads)
{
  // Two balls of radius 30 mm and over 65,536 triangles each, 10 mm apart along y: each lies almost
  // whole in the other's box, and their surfaces cross along a circle across the whole width in x.
  // On several threads their pair is searched in slabs across x; the pairs found are those of the
  // whole search on one thread (the test above checks that one against every pair of triangles).
  auto ballAt = [](double cy) { return reconstructSurface(ballStack(0.0, cy, 0.0, 30.0, 360, 0.5)); };
  const TriangleMesh a = ballAt(0.0), b = ballAt(10.0);
  ASSERT_GE(a.triangles.size(), 65536u);
  const std::vector<TrianglePair> whole = crossingTriangles({ &a, &b }, 1);
  ASSERT_GT(whole.size(), 1000u);
  // The crossings reach across x, so across every slab and their borders.
  double low = 1e9, high = -1e9;
  for (const auto& [first, second] : whole)
    for (const std::int32_t v : a.triangles[first.triangle])
    {
      low = std::min(low, a.points[static_cast<std::size_t>(v)].x);
      high = std::max(high, a.points[static_cast<std::size_t>(v)].x);
    }
  EXPECT_LT(low, -25.0);
  EXPECT_GT(high, 25.0);
  for (unsigned int threads : { 2u, 3u, 8u })
    EXPECT_EQ(crossingTriangles({ &a, &b }, threads), whole) << threads << " threads";
}

} // namespace slicemesh::testing

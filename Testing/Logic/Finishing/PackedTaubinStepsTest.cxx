// The Taubin pairs' packed step: each vertex moves by the factor towards the mean of exactly its own
// neighbours, however many it has (fewer than the eight slots, more, or none), and a bounded step
// stops on the ellipsoid around the start.
#include "Finishing/PackedTaubinSteps.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slicemesh;

namespace
{

/** Compressed rows of neighbours from lists. */
struct Rows
{
  std::vector<std::size_t> first{ 0 };
  std::vector<std::int32_t> ids;
  void add(const std::vector<std::int32_t>& neighbours)
  {
    ids.insert(ids.end(), neighbours.begin(), neighbours.end());
    first.push_back(ids.size());
  }
};

} // namespace

TEST(PackedTaubinSteps, EachVertexMovesTowardsTheMeanOfItsOwnNeighbours)
{
  // Vertex 0 has 11 neighbours (three past the slots), 1 has 3, 2 none; the others have vertex 0.
  std::vector<Point3> points(14);
  for (std::size_t v = 0; v < points.size(); ++v)
    points[v] = { 100.0 + 0.5 * static_cast<double>(v), -40.0 + 0.25 * static_cast<double>(v * v), 7.0 - static_cast<double>(v) };
  Rows rows;
  rows.add({ 1, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 });
  rows.add({ 0, 3, 13 });
  rows.add({});
  for (std::size_t v = 3; v < points.size(); ++v)
    rows.add({ 0 });
  const NeighbourSlots slots(rows.first, rows.ids);
  EXPECT_EQ(slots.more.size(), 3u);

  PackedPoints packed(points);
  std::vector<Float4> scratch = packed.data();
  const PackedBound free(packed.data(), {}, false);
  const double factor = 0.63;
  packedUmbrellaStep(packed.data(), slots, static_cast<float>(factor), scratch, free, 1);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    Point3 mean{};
    const std::size_t count = rows.first[v + 1] - rows.first[v];
    for (std::size_t i = rows.first[v]; i < rows.first[v + 1]; ++i)
    {
      const Point3& q = points[static_cast<std::size_t>(rows.ids[i])];
      mean = { mean.x + q.x / count, mean.y + q.y / count, mean.z + q.z / count };
    }
    if (count == 0)
      mean = points[v];
    const Point3 expected{ points[v].x + factor * (mean.x - points[v].x), points[v].y + factor * (mean.y - points[v].y),
                           points[v].z + factor * (mean.z - points[v].z) };
    const Point3 got = packed.unpack(v);
    // Single precision about the points' middle: a few micrometres' worth of rounding here at most.
    EXPECT_NEAR(got.x, expected.x, 1e-5) << v;
    EXPECT_NEAR(got.y, expected.y, 1e-5) << v;
    EXPECT_NEAR(got.z, expected.z, 1e-5) << v;
  }
  // The extra point the empty slots name stays at the origin.
  const Float4 zero = packed.data().back();
  EXPECT_EQ(zero[0], 0.0f);
  EXPECT_EQ(zero[1], 0.0f);
  EXPECT_EQ(zero[2], 0.0f);
}

TEST(PackedTaubinSteps, ABoundedStepStopsOnItsEllipsoid)
{
  // Vertex 0 pulled 10 mm along x by its neighbour; the bound is 0.5 mm along x.
  const std::vector<Point3> points{ { 1.0, 2.0, 3.0 }, { 11.0, 2.0, 3.0 } };
  Rows rows;
  rows.add({ 1 });
  rows.add({ 0 });
  const NeighbourSlots slots(rows.first, rows.ids);
  PackedPoints packed(points);
  const std::vector<Float4> start = packed.data();
  std::vector<Float4> scratch = start;
  const PackedBound bound(start, { 0.5, 2.0, 2.0 }, true);
  packedUmbrellaStep(packed.data(), slots, 0.63f, scratch, bound, 1);
  EXPECT_NEAR(packed.unpack(0).x, 1.5, 1e-6);
  EXPECT_NEAR(packed.unpack(1).x, 10.5, 1e-6);
  EXPECT_NEAR(packed.unpack(0).y, 2.0, 1e-6);

  // The pairs keep a held vertex where it started.
  TaubinPairs pairs(points, slots, { 0.5, 2.0, 2.0 }, true, { 1 });
  pairs.run(3, 0.63, -0.64, 1);
  std::vector<Point3> after(points.size());
  pairs.unpackInto(after);
  EXPECT_NEAR(after[1].x, 11.0, 1e-6);
  EXPECT_GT(after[0].x, 1.0);
  EXPECT_LE(after[0].x, 1.5 + 1e-6);
}

TEST(PackedTaubinSteps, PairsStopOnceTheyChangeNothingWithTheSamePoints)
{
  // An octahedron of 1 mm pressed by the filter against a bound of 0.1 mm: its points stop changing
  // within a few pairs. The run stops there, and its points are those of every pair run one by one.
  const std::vector<Point3> points{ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  Rows rows;
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    std::vector<std::int32_t> around;
    for (std::size_t u = 0; u < points.size(); ++u)
      if (u != v && u != (v ^ 1u)) // every vertex but itself and its opposite
        around.push_back(static_cast<std::int32_t>(u));
    rows.add(around);
  }
  const double lambda = 0.63, mu = 1.0 / (0.01 - 1.0 / lambda);
  const NeighbourSlots slots(rows.first, rows.ids);
  TaubinPairs early(points, slots, { 0.1, 0.1, 0.1 }, true, {});
  const int ran = early.run(200, lambda, mu, 1);
  EXPECT_LT(ran, 200);
  EXPECT_EQ(ran % TaubinPairs::fixedPointCheck, 0);
  TaubinPairs oneByOne(points, slots, { 0.1, 0.1, 0.1 }, true, {});
  for (int i = 0; i < 200; ++i)
    ASSERT_EQ(oneByOne.run(1, lambda, mu, 1), 1); // a single pair is never checked
  std::vector<Point3> a(points.size()), b(points.size());
  early.unpackInto(a);
  oneByOne.unpackInto(b);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    EXPECT_EQ(a[v].x, b[v].x) << v;
    EXPECT_EQ(a[v].y, b[v].y) << v;
    EXPECT_EQ(a[v].z, b[v].z) << v;
    EXPECT_NEAR(std::sqrt(a[v].x * a[v].x + a[v].y * a[v].y + a[v].z * a[v].z), 0.9, 1e-6) << v; // on its bound
  }
  // Unbounded, the filter keeps moving the points (towards their middle) all the pairs.
  TaubinPairs unbounded(points, slots, {}, false, {});
  EXPECT_EQ(unbounded.run(200, lambda, mu, 1), 200);
}

TEST(PackedTaubinSteps, SlotsGiveBackTheRowsTheyWereMadeFrom)
{
  // Every case of filling the slots: more neighbours than slots, exactly eight, a few, none
  // (isolated: itself in every slot), a vertex that is its own neighbour (a triangle that repeats a
  // corner), alone or first among others, and seven, whose last slot names the extra point.
  Rows rows;
  rows.add({ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 });
  rows.add({ 0, 2, 3, 4, 5, 6, 7, 8 });
  rows.add({ 0, 5 });
  rows.add({});
  rows.add({ 4 });
  rows.add({ 5, 0 });
  rows.add({ 0, 1, 2, 3, 4, 5, 7 });
  for (int v = 7; v < 12; ++v)
    rows.add({ 0, static_cast<std::int32_t>(v == 11 ? 7 : v + 1) });
  for (unsigned int threads : { 1u, 3u })
  {
    const NeighbourSlots slots(rows.first, rows.ids, threads);
    std::vector<std::size_t> first;
    std::vector<std::int32_t> ids;
    slots.rowsInto(first, ids, threads);
    EXPECT_EQ(first, rows.first) << threads << " threads";
    EXPECT_EQ(ids, rows.ids) << threads << " threads";
  }
}

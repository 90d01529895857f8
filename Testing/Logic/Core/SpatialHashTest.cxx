// The spatial hash of Core and the nearest-segment search built on it, against brute force.
#include "Core/NearestSegment.h"
#include "Core/SpatialHash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

using namespace slicemesh;

TEST(SpatialHash, CellsAreHalfOpenOnEitherSideOfZero)
{
  const SpatialHash hash(0.5);
  EXPECT_EQ(hash.cellOf(0.0), 0);
  EXPECT_EQ(hash.cellOf(0.49), 0);
  EXPECT_EQ(hash.cellOf(0.5), 1);
  EXPECT_EQ(hash.cellOf(-0.01), -1);
  EXPECT_EQ(hash.cellOf(-0.5), -1);
  EXPECT_EQ(hash.cellOf(-0.51), -2);
  const SpatialHash::CellRange cells = hash.cellsOf(Box2{ -0.7, 0.2, 1.1, 0.3 });
  EXPECT_EQ(cells.x0, -2);
  EXPECT_EQ(cells.x1, 2);
  EXPECT_EQ(cells.y0, 0);
  EXPECT_EQ(cells.y1, 0);
  const SpatialHash::CellRange around = hash.cellsWithin({ 0.1, -0.1 }, 0.6);
  EXPECT_EQ(around.x0, -2);
  EXPECT_EQ(around.x1, 2);
  EXPECT_EQ(around.y0, -3);
  EXPECT_EQ(around.y1, 1);
}

TEST(SpatialHash, VisitsCellByCellInInsertionOrderAndStopsAtTheFirstHit)
{
  SpatialHash hash(1.0);
  hash.insert(Point2{ 0.5, 1.5 }, 7); // cell (0, 1)
  hash.insert(Point2{ 1.5, 0.5 }, 3); // cell (1, 0)
  hash.insert(Point2{ 0.2, 0.2 }, 5); // cell (0, 0)
  hash.insert(Point2{ 0.8, 0.8 }, 4); // cell (0, 0), after 5
  hash.insert(SpatialHash::CellRange{ 0, 1, 1, 1 }, 9); // cells (0, 1) and (1, 1)
  std::vector<int> order;
  hash.forEachIn({ 0, 1, 0, 1 }, [&](int index) { order.push_back(index); });
  // x outer, y inner: (0, 0), (0, 1), (1, 0), (1, 1).
  EXPECT_EQ(order, (std::vector<int>{ 5, 4, 7, 9, 3, 9 }));
  auto listed = [&hash](long long x, long long y)
  {
    std::vector<int> indices;
    for (int index : hash.cell(x, y))
      indices.push_back(index);
    return indices;
  };
  EXPECT_EQ(listed(0, 0), (std::vector<int>{ 5, 4 }));
  EXPECT_EQ(listed(0, 1), (std::vector<int>{ 7, 9 }));
  EXPECT_TRUE(listed(5, -5).empty());

  std::vector<int> tested;
  EXPECT_TRUE(hash.anyIn({ 0, 1, 0, 1 }, [&](int index) {
    tested.push_back(index);
    return index == 7;
  }));
  EXPECT_EQ(tested, (std::vector<int>{ 5, 4, 7 }));
  EXPECT_FALSE(hash.anyIn({ 2, 3, 2, 3 }, [](int) { return true; }));
}

TEST(SpatialHash, FindsEveryPointWithinARadius)
{
  std::mt19937 random(12);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  std::vector<Point2> points(2000);
  SpatialHash hash(0.7);
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
  {
    points[i] = { coordinate(random), coordinate(random) };
    hash.insert(points[i], i);
  }
  for (double radius : { 0.1, 0.7, 2.3 })
    for (int query = 0; query < 200; ++query)
    {
      const Point2 p{ coordinate(random), coordinate(random) };
      std::set<int> found, expected;
      hash.forEachIn(hash.cellsWithin(p, radius), [&](int index) {
        if (distance(points[index], p) <= radius)
          found.insert(index);
      });
      for (int i = 0; i < static_cast<int>(points.size()); ++i)
        if (distance(points[i], p) <= radius)
          expected.insert(i);
      ASSERT_EQ(found, expected) << "radius " << radius << " at (" << p.x << ", " << p.y << ")";
    }
}

TEST(SpatialHash, BoxesOfSpaceAreFiledByHeightToo)
{
  // A tall wall's triangles, one above the other at the same place in plan: a box finds only those
  // whose cells of space it shares, where columns of the plane would give it every one.
  SpatialHash hash(1.0);
  auto boxAt = [](double z)
  {
    BoundingBox box;
    box.add(Point3{ 0.2, 0.2, z });
    box.add(Point3{ 0.8, 0.3, z + 0.5 });
    return box;
  };
  for (int k = 0; k < 100; ++k)
    hash.insert(hash.cellsOf(boxAt(k)), k);
  const SpatialHash::CellRange cells = hash.cellsOf(boxAt(40.7));
  EXPECT_EQ(cells.z0, 40);
  EXPECT_EQ(cells.z1, 41);
  std::vector<int> found;
  hash.forEachIn(cells, [&](int k) { found.push_back(k); });
  EXPECT_EQ(found, (std::vector<int>{ 40, 41 }));
  // A planar range is the cells of height 0: the same box's plan finds the one at z = 0 only.
  std::vector<int> inPlane;
  hash.forEachIn(hash.cellsOf(Box2{ 0.2, 0.2, 0.8, 0.3 }), [&](int k) { inPlane.push_back(k); });
  EXPECT_EQ(inPlane, (std::vector<int>{ 0 }));
}

TEST(NearestSegment, AgreesWithBruteForceNearAndFarFromTheSegments)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0), step(-1.0, 1.0);
  std::vector<NearestSegment::Segment> segments;
  for (int s = 0; s < 300; ++s)
  {
    const Point2 a{ coordinate(random), coordinate(random) };
    segments.push_back({ a, { a.x + step(random), a.y + step(random) } });
  }
  const NearestSegment nearest(segments, 1.0);
  std::uniform_real_distribution<double> anywhere(-40.0, 40.0);
  for (int query = 0; query < 500; ++query)
  {
    const Point2 p{ anywhere(random), anywhere(random) };
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : segments)
      best = std::min(best, distanceToSegment(p, a, b));
    Point2 closest;
    ASSERT_EQ(nearest.nearest(p, &closest), best) << "at (" << p.x << ", " << p.y << ")";
    EXPECT_NEAR(distance(p, closest), best, 1e-12);
  }
  EXPECT_TRUE(std::isinf(NearestSegment({}, 1.0).distance({ 0.0, 0.0 })));
}

TEST(NearestSegment, WithinALimitTheDistanceIsExactAndBeyondItNotUnder)
{
  // A ring of short segments, asked from inside, on and outside it with limits around the answer.
  std::vector<NearestSegment::Segment> segments;
  for (int k = 0; k < 64; ++k)
  {
    const double a = 2.0 * M_PI * k / 64, b = 2.0 * M_PI * (k + 1) / 64;
    segments.push_back({ { 30.0 * std::cos(a), 30.0 * std::sin(a) }, { 30.0 * std::cos(b), 30.0 * std::sin(b) } });
  }
  const NearestSegment nearest(segments, 2.0);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> anywhere(-50.0, 50.0), limit(0.0, 40.0);
  for (int query = 0; query < 2000; ++query)
  {
    const Point2 p{ anywhere(random), anywhere(random) };
    const double exact = nearest.distance(p), bound = limit(random);
    const double within = nearest.distanceWithin(p, bound);
    if (exact < bound)
      ASSERT_EQ(within, exact) << "at (" << p.x << ", " << p.y << "), limit " << bound;
    else
      ASSERT_GE(within, bound) << "at (" << p.x << ", " << p.y << "), limit " << bound;
  }
}

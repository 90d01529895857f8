#include "Correspondence/ContourCorrespondence.h"
#include "ContourStacks.h"
#include "Correspondence/PolygonProximity.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

const CorrespondenceGroup* groupWithLower(const SlabCorrespondence& c, std::size_t i)
{
  for (const CorrespondenceGroup& g : c.groups)
    for (std::size_t k : g.lower)
      if (k == i)
        return &g;
  return nullptr;
}

bool overlap(const Polygon2& a, const Polygon2& b)
{
  return regionsOverlap(IndexedPolygon(a), IndexedPolygon(b));
}

} // namespace

TEST(PolygonProximity, OverlapDecidesDegenerateContacts)
{
  const Polygon2 square = rectangle(0, 0, 4, 4);
  EXPECT_TRUE(overlap(square, rectangle(0, 0, 4, 4)));              // identical: no vertex strictly inside
  EXPECT_TRUE(overlap(square, { { 2, 0 }, { 4, 2 }, { 2, 4 }, { 0, 2 } })); // inscribed diamond: vertices on edges
  EXPECT_FALSE(overlap(square, rectangle(4, 0, 8, 4)));             // sharing an edge only
  EXPECT_FALSE(overlap(square, rectangle(4, 4, 8, 8)));             // sharing a corner only
  EXPECT_TRUE(overlap(square, rectangle(1, -1, 3, 5)));             // a cross: no vertex inside, edges cross
  EXPECT_TRUE(overlap(square, rectangle(1, 1, 2, 2)));              // nested
  EXPECT_TRUE(overlap(rectangle(1, 1, 2, 2), square));
  EXPECT_TRUE(overlap(square, rectangle(0, 0, 2, 4)));              // a half on the same walls (voxel slices)
  EXPECT_FALSE(overlap(square, rectangle(5, 0, 6, 4)));
}

TEST(PolygonProximity, BoundaryDistance)
{
  const IndexedPolygon a(circle(0, 0, 5, 200));
  const Polygon2 far = circle(12, 0, 5, 200);
  const IndexedPolygon b(far);
  EXPECT_NEAR(boundaryDistance(a, b, 3.0), 2.0, 1e-9);
  EXPECT_GT(boundaryDistance(a, b, 1.5), 1.5);
}

TEST(ContourCorrespondence, OneToOne)
{
  const SlabCorrespondence c = matchContours({ circle(0, 0, 5, 40) }, { circle(3, 0, 5, 40, true) });
  ASSERT_EQ(c.groups.size(), 1u);
  EXPECT_EQ(c.groups[0].shape(), GroupShape::OneToOne);
  EXPECT_EQ(c.groups[0].contact(), GroupContact::Overlap);
  EXPECT_FALSE(c.groups[0].holes);
}

TEST(ContourCorrespondence, OneToTwoAndTwoToOne)
{
  const std::vector<Polygon2> trunk{ circle(0, 0, 10, 64) };
  const std::vector<Polygon2> branches{ circle(-5, 0, 4, 32), circle(5, 0, 4, 32), circle(40, 0, 4, 32) };
  const SlabCorrespondence up = matchContours(trunk, branches);
  ASSERT_EQ(up.groups.size(), 2u);
  EXPECT_EQ(up.groups[0].shape(), GroupShape::OneToMany);
  EXPECT_EQ(up.groups[0].upper, (std::vector<std::size_t>{ 0, 1 }));
  EXPECT_EQ(up.groups[1].shape(), GroupShape::UpperOnly);
  EXPECT_EQ(up.groups[1].contact(), GroupContact::None);

  const SlabCorrespondence down = matchContours(branches, trunk);
  ASSERT_EQ(down.groups.size(), 2u);
  EXPECT_EQ(down.groups[0].shape(), GroupShape::ManyToOne);
  EXPECT_EQ(down.groups[0].lower, (std::vector<std::size_t>{ 0, 1 }));
  EXPECT_EQ(down.groups[1].shape(), GroupShape::LowerOnly);
}

TEST(ContourCorrespondence, TwoToTwo)
{
  const std::vector<Polygon2> lower{ rectangle(0, 0, 4, 2), rectangle(6, 0, 10, 2) };
  const std::vector<Polygon2> upper{ rectangle(3, 0, 7, 1), rectangle(3, 1.5, 7, 2) };
  const SlabCorrespondence c = matchContours(lower, upper);
  ASSERT_EQ(c.groups.size(), 1u);
  EXPECT_EQ(c.groups[0].shape(), GroupShape::ManyToMany);
  EXPECT_EQ(c.groups[0].links.size(), 4u);
}

TEST(ContourCorrespondence, HolesMatchHolesOnly)
{
  // The lower hole lies inside the upper outer boundary's region, but orientations differ: no link.
  const std::vector<Polygon2> lower{ circle(0, 0, 10, 64), circle(0, 0, 4, 32) };
  const std::vector<Polygon2> upper{ circle(1, 0, 10, 64, true), circle(1, 0, 4, 32, false) };
  const SlabCorrespondence c = matchContours(lower, upper);
  ASSERT_EQ(c.groups.size(), 2u);
  const CorrespondenceGroup* holes = groupWithLower(c, 1);
  ASSERT_NE(holes, nullptr);
  EXPECT_TRUE(holes->holes);
  EXPECT_EQ(holes->upper, (std::vector<std::size_t>{ 1 }));
  EXPECT_EQ(holes->shape(), GroupShape::OneToOne);
  EXPECT_FALSE(groupWithLower(c, 0)->holes);

  // A hole facing only an outer boundary of the other slice stays unmatched.
  const SlabCorrespondence lonely = matchContours(lower, { circle(0, 0, 10, 64) });
  EXPECT_EQ(groupWithLower(lonely, 1)->shape(), GroupShape::LowerOnly);
}

TEST(ContourCorrespondence, DistanceThresholdOnAndOff)
{
  const std::vector<Polygon2> lower{ circle(0, 0, 5, 200) };
  const std::vector<Polygon2> upper{ circle(12, 0, 5, 200) }; // a 2 mm gap
  const SlabCorrespondence off = matchContours(lower, upper, 0.0);
  ASSERT_EQ(off.groups.size(), 2u);
  EXPECT_EQ(off.groups[0].shape(), GroupShape::LowerOnly);
  EXPECT_EQ(off.groups[1].shape(), GroupShape::UpperOnly);

  const SlabCorrespondence tooShort = matchContours(lower, upper, 1.5);
  EXPECT_EQ(tooShort.groups.size(), 2u);

  const SlabCorrespondence on = matchContours(lower, upper, 2.5);
  ASSERT_EQ(on.groups.size(), 1u);
  EXPECT_EQ(on.groups[0].shape(), GroupShape::OneToOne);
  EXPECT_EQ(on.groups[0].contact(), GroupContact::WithinDistance);
  ASSERT_EQ(on.groups[0].links.size(), 1u);
  EXPECT_NEAR(on.groups[0].links[0].distance, 2.0, 1e-9);

  // One branch overlaps, the other is only near: a mixed one-to-two group.
  const SlabCorrespondence mixed =
    matchContours({ circle(0, 0, 5, 100) }, { circle(2, 0, 3, 60), circle(-7, 0, 1, 30) }, 1.5);
  ASSERT_EQ(mixed.groups.size(), 1u);
  EXPECT_EQ(mixed.groups[0].shape(), GroupShape::OneToMany);
  EXPECT_EQ(mixed.groups[0].contact(), GroupContact::Mixed);
  EXPECT_TRUE(mixed.groups[0].hasDistanceOnlyLink());

  EXPECT_THROW(matchContours(lower, upper, -1.0), Error);
}

TEST(ContourCorrespondence, LargeContoursAreFast)
{
  // Nearly coincident 5000-point circles: no vertex of one is inside the other at the start of the
  // scan for the rotated copy, so the crossing grid does the work.
  const std::vector<Polygon2> lower{ circle(0, 0, 50, 5000), circle(200, 0, 50, 5000) };
  const std::vector<Polygon2> upper{ circle(0, 0, 50, 5000, false, 1e-4), circle(311, 0, 50, 5000) };
  const auto start = std::chrono::steady_clock::now();
  const SlabCorrespondence c = matchContours(lower, upper, 20.0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ timing   ] correspondence of 2 x 2 contours of 5000 points: " << seconds * 1e3 << " ms\n";
  ASSERT_EQ(c.groups.size(), 2u);
  EXPECT_EQ(c.groups[0].contact(), GroupContact::Overlap);
  EXPECT_EQ(c.groups[1].contact(), GroupContact::WithinDistance);
  EXPECT_LT(seconds, 1.0);
}

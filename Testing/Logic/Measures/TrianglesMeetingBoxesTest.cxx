// Which triangles of a mesh meet each of a set of boxes: every one whose box shares a point with
// it, in increasing order, whatever the boxes' sizes and the number of threads.
#include "ContourStacks.h"
#include "Measures/TrianglesMeetingBoxes.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slicemesh::testing
{
namespace
{

TEST(TrianglesMeetingBoxes, EveryTriangleWhoseBoxMeetsEachBox)
{
  const ContourStack stack = sliceStack(-9.5, 9.5, 1.0, [](double z)
                                        { return std::vector<Polygon2>{ circle(0.0, 0.0, std::sqrt(100.0 - z * z), 64) }; });
  const TriangleMesh ball = reconstructSurface(stack);
  // Small boxes on and off the surface, boxes spanning many cells, one holding the whole ball, one
  // touching a vertex's coordinate exactly, one far away.
  std::vector<BoundingBox> boxes;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> at(-12.0, 12.0), size(0.05, 2.0);
  for (int k = 0; k < 200; ++k)
  {
    BoundingBox box;
    const Point3 low{ at(random), at(random), at(random) };
    const double s = k % 20 == 0 ? 12.0 : size(random);
    box.add(low);
    box.add(Point3{ low.x + s, low.y + s, low.z + s });
    boxes.push_back(box);
  }
  BoundingBox whole = boxOfTriangles(ball), touching, far;
  const Point3& v = ball.points[static_cast<std::size_t>(ball.triangles[100][0])];
  touching.add(Point3{ v.x, v.y, v.z });
  touching.add(Point3{ v.x - 0.01, v.y - 0.01, v.z - 0.01 });
  far.add(Point3{ 100.0, 100.0, 100.0 });
  boxes.push_back(whole);
  boxes.push_back(touching);
  boxes.push_back(far);
  std::vector<std::uint32_t> expected;
  std::vector<std::size_t> expectedStart{ 0 };
  for (const BoundingBox& box : boxes)
  {
    for (std::size_t t = 0; t < ball.triangles.size(); ++t)
      if (boxOfTriangle(ball, t).overlaps(box))
        expected.push_back(static_cast<std::uint32_t>(t));
    expectedStart.push_back(expected.size());
  }
  EXPECT_EQ(expectedStart[boxes.size() - 2] - expectedStart[boxes.size() - 3], ball.triangles.size()); // the whole box
  EXPECT_GT(expectedStart[boxes.size() - 1] - expectedStart[boxes.size() - 2], 0u);                   // touching
  EXPECT_EQ(expectedStart[boxes.size()], expectedStart[boxes.size() - 1]);                            // far
  for (unsigned int threads : { 1u, 2u, 8u })
  {
    const TrianglesMeeting meeting = trianglesMeetingBoxes(ball, boxes, threads);
    EXPECT_EQ(meeting.start, expectedStart) << threads << " threads";
    EXPECT_EQ(meeting.triangles, expected) << threads << " threads";
  }
  EXPECT_EQ(trianglesMeetingBoxes(ball, {}).start, std::vector<std::size_t>{ 0 });
}

} // namespace
} // namespace slicemesh::testing

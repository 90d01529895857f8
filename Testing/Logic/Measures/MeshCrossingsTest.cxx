// crossingMeshes: which of several closed meshes (no shared vertices) cross each other.
#include "ContourStacks.h"
#include "Measures/MeshCrossings.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

namespace slicemesh::testing
{
namespace
{

/** A closed ball of radius 6 mm about (cx, 0, 0), sliced every 1.5 mm. */
TriangleMesh ball(double cx)
{
  ContourStack stack;
  stack.sliceSpacing = 1.5;
  for (double z = -5.25; z <= 5.3; z += 1.5)
    stack.slices.push_back({ z, { circle(cx, 0.0, std::sqrt(36.0 - z * z), 48) } });
  return reconstructSurface(stack);
}

TEST(MeshCrossings, OnlyMeshesThatMeetAreNamed)
{
  const TriangleMesh a = ball(0.0), apart = ball(40.0), overlapping = ball(8.0), far = ball(60.0);
  std::size_t pairs = 99;
  // Apart (boxes do not even overlap): nothing.
  EXPECT_TRUE(crossingMeshes({ &a, &apart }, pairs).empty());
  EXPECT_EQ(pairs, 0u);
  // Two balls 8 mm apart overlap: their surfaces cross along a circle, and only that pair is named.
  const auto crossing = crossingMeshes({ &a, &apart, &overlapping, &far }, pairs);
  ASSERT_EQ(crossing.size(), 1u);
  EXPECT_EQ(crossing[0], (std::pair<std::size_t, std::size_t>{ 0, 2 }));
  EXPECT_GT(pairs, 10u); // many triangle pairs along the circle of contact
}

TEST(MeshCrossings, AMeshDoesNotCrossItself)
{
  const TriangleMesh a = ball(0.0);
  std::size_t pairs = 99;
  EXPECT_TRUE(crossingMeshes({ &a }, pairs).empty()); // its own neighbouring triangles touch, by design
  EXPECT_EQ(pairs, 0u);
}

} // namespace
} // namespace slicemesh::testing

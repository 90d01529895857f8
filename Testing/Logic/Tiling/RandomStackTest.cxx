// Property test: stacks of random star-shaped contours (with and without holes) whose neighbours
// cross each other everywhere must still give a valid closed surface.
#include "ContourStacks.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

using namespace slicemesh;
using slicemesh::testing::randomShiftedStar;
using slicemesh::testing::randomStar;

class RandomStack : public ::testing::TestWithParam<int>
{
};

TEST_P(RandomStack, IsClosedManifoldAndSelfIntersectionFree)
{
  std::mt19937 rng(GetParam());
  std::uniform_real_distribution<double> shift(-1.5, 1.5);
  std::uniform_int_distribution<int> points(12, 60);
  const bool withHole = GetParam() % 2 == 0;
  const double dz = GetParam() % 3 == 0 ? 3.0 : 1.0;
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (int k = 0; k < 8; ++k)
  {
    Slice slice{ k * dz, {} };
    slice.contours.push_back(randomShiftedStar(rng, shift, points, 10.0, k % 2 == 1));
    if (withHole && k > 1 && k < 6)
      slice.contours.push_back(randomShiftedStar(rng, shift, points, 3.0, k % 3 == 0));
    stack.slices.push_back(slice);
  }
  ReconstructionOptions options;
  options.capPlacement = GetParam() % 4 == 1 ? CapPlacement::AtSlice : CapPlacement::HalfSliceBeyond;
  const TriangleMesh mesh = reconstructSurface(stack, options);
  const MeshValidation v = validateMesh(mesh);
  EXPECT_TRUE(v.valid()) << v.summary() << "; non-manifold edges " << v.nonManifoldEdges << ", vertices "
                         << v.nonManifoldVertices << ", inconsistent " << v.inconsistentEdges << ", degenerate "
                         << v.degenerateTriangles;
  // A hole open at neither end is a closed cavity: a second sphere-like boundary surface.
  EXPECT_EQ(v.components, withHole ? 2u : 1u);
  EXPECT_EQ(v.eulerCharacteristic, withHole ? 4 : 2);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomStack, ::testing::Range(1, 41));

// Two blobs per slice drifting far between slices: contours that partly overlap, branch, merge
// and end (caps next to tilings in the same slab).
class DriftingBlobs : public ::testing::TestWithParam<int>
{
};

TEST_P(DriftingBlobs, IsClosedManifoldAndSelfIntersectionFree)
{
  std::mt19937 rng(1000 + GetParam());
  std::uniform_real_distribution<double> shift(-7.0, 7.0), size(2.0, 8.0);
  std::uniform_int_distribution<int> points(6, 40);
  ContourStack stack;
  stack.sliceSpacing = 1.0 + GetParam() % 3;
  for (int k = 0; k < 10; ++k)
  {
    Slice slice{ k * stack.sliceSpacing, {} };
    // Two disjoint blobs: left and right of x = 0.
    const double r1 = size(rng), r2 = size(rng);
    // Drawn one by one, not as a call's arguments (see randomShiftedStar).
    int n = points(rng);
    double cy = shift(rng), cx = -r1 * 1.3 - std::abs(shift(rng)) * 0.3;
    slice.contours.push_back(randomStar(rng, cx, cy, r1, n, false));
    if (k % 4 != 3)
    {
      n = points(rng);
      cy = shift(rng);
      cx = r2 * 1.3 + std::abs(shift(rng)) * 0.3;
      slice.contours.push_back(randomStar(rng, cx, cy, r2, n, true));
    }
    stack.slices.push_back(slice);
  }
  ReconstructionOptions options;
  options.capPlacement = GetParam() % 2 ? CapPlacement::AtSlice : CapPlacement::HalfSliceBeyond;
  const TriangleMesh mesh = reconstructSurface(stack, options);
  const MeshValidation v = validateMesh(mesh);
  EXPECT_TRUE(v.valid()) << v.summary() << "; non-manifold edges " << v.nonManifoldEdges << ", vertices "
                         << v.nonManifoldVertices << ", inconsistent " << v.inconsistentEdges << ", degenerate "
                         << v.degenerateTriangles;
  EXPECT_EQ(v.eulerCharacteristic % 2, 0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, DriftingBlobs, ::testing::Range(1, 61));

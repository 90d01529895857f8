// prismVolume: each slice's area times its thickness, holes told by nesting whatever their winding.
#include "ContourStacks.h"
#include "Measures/StackVolume.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slicemesh::testing
{
namespace
{

/** The area of a regular n-gon inscribed in a circle of radius r. */
double polygonArea(double r, int n)
{
  return 0.5 * n * r * r * std::sin(2.0 * M_PI / n);
}

TEST(StackVolume, AnnuliCountTheirHoleWhateverItsWinding)
{
  for (bool holeClockwise : { true, false })
  {
    ContourStack stack;
    stack.sliceSpacing = 2.0;
    for (int k = 0; k < 5; ++k)
      stack.slices.push_back({ 2.0 * k, { circle(0.0, 0.0, 10.0, 64, false), circle(0.0, 0.0, 5.0, 48, holeClockwise) } });
    const double ring = polygonArea(10.0, 64) - polygonArea(5.0, 48);
    EXPECT_NEAR(prismVolume(stack), 5 * 2.0 * ring, 1e-9 * ring);
  }
}

TEST(StackVolume, WithoutASpacingEachSliceTakesHalfOfEachGap)
{
  // Slices at 0, 1 and 4 mm: thicknesses 1 (the one gap of the end slice), 2 (half of 1 + 3) and 3.
  ContourStack stack;
  for (double z : { 0.0, 1.0, 4.0 })
    stack.slices.push_back({ z, { rectangle(0.0, 0.0, 2.0, 3.0) } });
  EXPECT_NEAR(prismVolume(stack), 6.0 * (1.0 + 2.0 + 3.0), 1e-9);
  // An island inside a hole counts again.
  stack.slices[1].contours.push_back(rectangle(0.5, 0.5, 1.5, 2.5));
  stack.slices[1].contours.push_back(rectangle(0.75, 1.0, 1.25, 2.0));
  EXPECT_NEAR(prismVolume(stack), 6.0 * 6.0 - 2.0 * 2.0 + 0.5 * 2.0, 1e-9);
}

TEST(StackVolume, AMissingSliceIsSharedByItsNeighbours)
{
  // Slices every 1 mm with the one at 2 mm missing: its millimetre is counted half to each neighbour,
  // as the tiling bridges it; five slices' worth in all.
  ContourStack stack;
  stack.sliceSpacing = 1.0;
  for (double z : { 0.0, 1.0, 3.0, 4.0 })
    stack.slices.push_back({ z, { rectangle(0.0, 0.0, 2.0, 3.0) } });
  EXPECT_NEAR(prismVolume(stack), 6.0 * 5.0, 1e-9);
}

} // namespace
} // namespace slicemesh::testing

// In-plane Gaussian smoothing of the mask before contour extraction: the voxel staircase goes,
// the boundary stays where it was.
#include "ContourExtraction.h"
#include "SliceSmoothing.h"
#include "TestVolumes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** A disk of radius r (mm) centred in every slice of a size x size x 3 mask. */
MaskVolume::Pointer diskMask(long size, double spacing, double r)
{
  MaskVolume::Pointer mask = makeMask({ static_cast<std::size_t>(size), static_cast<std::size_t>(size), 3 },
                                      { spacing, spacing, 2.0 });
  const double c = 0.5 * (size - 1) * spacing;
  for (long k = 0; k < 3; ++k)
    for (long j = 0; j < size; ++j)
      for (long i = 0; i < size; ++i)
        setVoxel(mask.GetPointer(), i, j, k,
                 static_cast<unsigned char>(std::hypot(i * spacing - c, j * spacing - c) <= r ? 1 : 0));
  return mask;
}

struct Radial
{
  double mean = 0.0, rms = 0.0; ///< mean radius and RMS deviation from it (mm)
};

Radial radialStatistics(const Polygon2& contour, double c)
{
  std::vector<double> radii;
  for (const Point2& p : contour)
    radii.push_back(std::hypot(p.x - c, p.y - c));
  Radial r;
  r.mean = std::accumulate(radii.begin(), radii.end(), 0.0) / radii.size();
  for (double v : radii)
    r.rms += (v - r.mean) * (v - r.mean);
  r.rms = std::sqrt(r.rms / radii.size());
  return r;
}

} // namespace

TEST(SliceSmoothing, KernelSumsToOneAndKeepsAConstant)
{
  EXPECT_EQ(gaussianRadius(0.0, 1.0), 0);
  EXPECT_EQ(gaussianRadius(1.0, 0.5), 6);
  std::vector<float> image(40 * 30, 1.0f);
  smoothSlice(image.data(), 40, 30, 0.5, 0.7, 1.0);
  // Far from the border (zeros outside) a constant stays constant.
  EXPECT_NEAR(image[15 * 40 + 20], 1.0f, 1e-5);
  EXPECT_LT(image[0], 0.5f);
  // A single pixel spreads symmetrically and keeps its mass.
  std::vector<float> impulse(21 * 21, 0.0f);
  impulse[10 * 21 + 10] = 1.0f;
  smoothSlice(impulse.data(), 21, 21, 1.0, 1.0, 1.5);
  EXPECT_NEAR(std::accumulate(impulse.begin(), impulse.end(), 0.0), 1.0, 1e-5);
  EXPECT_FLOAT_EQ(impulse[10 * 21 + 7], impulse[10 * 21 + 13]);
  EXPECT_FLOAT_EQ(impulse[7 * 21 + 10], impulse[10 * 21 + 7]);
}

TEST(SliceSmoothing, SmoothedContoursLoseTheStaircaseNotTheSize)
{
  const double spacing = 0.8, r = 12.0;
  const long size = 40;
  const double c = 0.5 * (size - 1) * spacing;
  const MaskVolume::Pointer mask = diskMask(size, spacing, r);
  const ContourStack raw = extractContours(mask);
  const ContourStack smooth = extractContours(mask, 1.0);
  ASSERT_EQ(smooth.slices.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
  {
    ASSERT_EQ(raw.slices[k].contours.size(), 1u);
    ASSERT_EQ(smooth.slices[k].contours.size(), 1u);
  }
  const Radial before = radialStatistics(raw.slices[1].contours[0], c);
  const Radial after = radialStatistics(smooth.slices[1].contours[0], c);
  std::printf("radius %.3f rms %.3f mm -> smoothed radius %.3f rms %.3f mm\n", before.mean, before.rms, after.mean,
              after.rms);
  EXPECT_LT(after.rms, 0.5 * before.rms);
  // The 0.5 level of a smoothed disk moves inwards by about sigma^2 / 2r (curvature), here 0.04 mm.
  EXPECT_NEAR(after.mean, before.mean, 0.15);
  EXPECT_NEAR(after.mean, r, 0.3);
}

TEST(SliceSmoothing, ContoursCloseAtTheImageBorder)
{
  // The disk fills the image to its border: the padding must be wide enough for the kernel.
  const MaskVolume::Pointer mask = diskMask(20, 1.0, 30.0);
  const ContourStack smooth = extractContours(mask, 2.0);
  ASSERT_EQ(smooth.slices[0].contours.size(), 1u);
  for (const Point2& p : smooth.slices[0].contours[0])
  {
    EXPECT_GT(p.x, -1.5);
    EXPECT_LT(p.x, 20.5);
  }
}

#include "Core/SliceMeshTypes.h"
#include "FiniteHistogram.h"
#include "OtsuThresholds.h"
#include "TestVolumes.h"
#include "VolumeSegmentation.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>
#include <random>

namespace slicemesh
{
namespace
{

using testing::makeVolume;

std::size_t countInside(const MaskVolume* mask)
{
  std::size_t count = 0;
  for (std::size_t n = 0; n < mask->GetBufferedRegion().GetNumberOfPixels(); ++n)
    count += mask->GetBufferPointer()[n] == 1;
  return count;
}

/** Every mask voxel is 1 exactly where expected(value of the volume voxel) holds, else 0. */
template <typename Expected>
void expectMask(const ScalarVolume* volume, const MaskVolume* mask, Expected expected)
{
  for (std::size_t n = 0; n < volume->GetBufferedRegion().GetNumberOfPixels(); ++n)
    ASSERT_EQ(mask->GetBufferPointer()[n], expected(volume->GetBufferPointer()[n]) ? 1 : 0) << "voxel " << n;
}

/** 10x10x10 with labels: 1 in a slab, 2 in a cube, 5 in one voxel, 0 elsewhere. */
ScalarVolume::Pointer labelVolume()
{
  auto volume = makeVolume({ 10, 10, 10 }, { 0.8, 0.8, 2.0 });
  ScalarVolume::PointType origin;
  origin.Fill(-3.0);
  volume->SetOrigin(origin);
  for (long k = 0; k < 10; ++k)
    for (long j = 0; j < 10; ++j)
      for (long i = 0; i < 10; ++i)
      {
        float label = 0.0f;
        if (k == 1)
          label = 1.0f;
        if (i >= 3 && i < 6 && j >= 3 && j < 6 && k >= 4 && k < 7)
          label = 2.0f;
        if (i == 8 && j == 8 && k == 8)
          label = 5.0f;
        volume->SetPixel({ { i, j, k } }, label);
      }
  return volume;
}

std::string errorMessageOf(const ScalarVolume* volume, const SegmentationOptions& options)
{
  try
  {
    segmentVolume(volume, options);
  }
  catch (const Error& error)
  {
    return error.what();
  }
  ADD_FAILURE() << "no slicemesh::Error thrown";
  return {};
}

TEST(VolumeSegmentation, LabelSelectsThatLabelOnly)
{
  const auto volume = labelVolume();
  SegmentationOptions options;
  options.label = 2;
  const MaskVolume::Pointer mask = segmentVolume(volume, options);
  expectMask(volume.GetPointer(), mask.GetPointer(), [](float v) { return v == 2.0f; });
  EXPECT_EQ(countInside(mask), 27u);
  EXPECT_EQ(mask->GetSpacing(), volume->GetSpacing());
  EXPECT_EQ(mask->GetOrigin(), volume->GetOrigin());
  EXPECT_EQ(mask->GetDirection(), volume->GetDirection());
}

TEST(VolumeSegmentation, LabelMapWithoutLabelTakesEveryNonZeroVoxel)
{
  const auto volume = labelVolume();
  const MaskVolume::Pointer mask = segmentVolume(volume, SegmentationOptions{});
  expectMask(volume.GetPointer(), mask.GetPointer(), [](float v) { return v != 0.0f; });
  EXPECT_EQ(countInside(mask), 100u + 27u + 1u);
}

TEST(VolumeSegmentation, MissingLabelListsTheLabelsPresent)
{
  const auto volume = labelVolume();
  SegmentationOptions options;
  options.label = 7;
  const std::string message = errorMessageOf(volume, options);
  EXPECT_NE(message.find("label 7"), std::string::npos) << message;
  EXPECT_NE(message.find("1, 2, 5"), std::string::npos) << message;
}

TEST(VolumeSegmentation, LongLabelListIsCut)
{
  // Labels 1 to 30, three voxels each in a row (a label map's neighbours are mostly equal: one voxel
  // each, touching, reads as an image's intensities).
  auto volume = makeVolume({ 90, 1, 1 });
  for (long i = 0; i < 90; ++i)
    volume->SetPixel({ { i, 0, 0 } }, static_cast<float>(i / 3 + 1));
  SegmentationOptions options;
  options.label = 99;
  const std::string message = errorMessageOf(volume, options);
  EXPECT_NE(message.find("19, 20, ..."), std::string::npos) << message;
  EXPECT_EQ(message.find("21"), std::string::npos) << message;
}

TEST(VolumeSegmentation, AllZeroLabelMapIsAnError)
{
  const auto volume = makeVolume({ 4, 4, 4 });
  const std::string message = errorMessageOf(volume, SegmentationOptions{});
  EXPECT_NE(message.find("nothing to mesh"), std::string::npos) << message;
}

/** A noisy bimodal volume: background around 10, a cube around 100, fractional values. */
ScalarVolume::Pointer grayscaleVolume()
{
  auto volume = makeVolume({ 20, 20, 20 });
  std::mt19937 random(5);
  std::normal_distribution<float> noise(0.0f, 3.0f);
  for (long k = 0; k < 20; ++k)
    for (long j = 0; j < 20; ++j)
      for (long i = 0; i < 20; ++i)
      {
        const bool object = i >= 5 && i < 15 && j >= 5 && j < 15 && k >= 5 && k < 15;
        volume->SetPixel({ { i, j, k } }, (object ? 100.0f : 10.0f) + noise(random));
      }
  return volume;
}

TEST(VolumeSegmentation, ThresholdKeepsVoxelsAtOrAboveIt)
{
  const auto volume = grayscaleVolume();
  SegmentationOptions options;
  options.threshold = 12.0;
  const MaskVolume::Pointer mask = segmentVolume(volume, options);
  expectMask(volume.GetPointer(), mask.GetPointer(), [](float v) { return v >= 12.0f; });
  EXPECT_GT(countInside(mask), 1000u); // the cube and part of the background noise
}

TEST(VolumeSegmentation, OtsuSeparatesTheTwoPopulations)
{
  const auto volume = grayscaleVolume();
  const MaskVolume::Pointer mask = segmentVolume(volume, SegmentationOptions{});
  expectMask(volume.GetPointer(), mask.GetPointer(), [](float v) { return v > 55.0f; });
  EXPECT_EQ(countInside(mask), 1000u);
}

TEST(VolumeSegmentation, ManyOtsuThresholdsComeBackInOrderInsideTheRange)
{
  // Five thresholds or more: ITK's calculator tries every placement in the histogram, which in 256
  // bins did not end for minutes (the option allows up to eight); fewer bins past four.
  const auto volume = grayscaleVolume();
  const auto range = finiteIntensityRange(volume);
  ASSERT_TRUE(range);
  for (const unsigned int count : { 5u, 8u })
  {
    SCOPED_TRACE(count);
    const std::vector<double> thresholds = otsuThresholds(volume, count);
    ASSERT_EQ(thresholds.size(), count);
    EXPECT_TRUE(std::is_sorted(thresholds.begin(), thresholds.end()));
    EXPECT_GE(thresholds.front(), range->first);
    EXPECT_LE(thresholds.back(), range->second);
    // Below the object (100 +- 3) and above the bulk of the background (10 +- 3), a threshold keeps
    // the object a class of its own, however many split the background.
    EXPECT_TRUE(std::any_of(thresholds.begin(), thresholds.end(), [](double t) { return t > 15.0 && t < 88.0; }));
  }
}

TEST(VolumeSegmentation, TheFiniteHistogramIsITKsOnAFiniteVolume)
{
  // The same bounds and counts as ITK's generator: Otsu's thresholds (and so the meshes) of a
  // volume without NaN or infinity are unchanged.
  const auto volume = grayscaleVolume();
  using Generator = itk::Statistics::ScalarImageToHistogramGenerator<ScalarVolume>;
  auto generator = Generator::New();
  generator->SetInput(volume);
  generator->SetNumberOfBins(256);
  generator->Compute();
  const IntensityHistogram* itk = generator->GetOutput();
  const IntensityHistogram::Pointer finite = finiteIntensityHistogram(volume, 256);
  ASSERT_EQ(finite->Size(), itk->Size());
  for (unsigned int bin = 0; bin < itk->Size(); ++bin)
  {
    EXPECT_EQ(finite->GetFrequency(bin), itk->GetFrequency(bin)) << bin;
    EXPECT_EQ(finite->GetBinMin(0, bin), itk->GetBinMin(0, bin)) << bin;
    EXPECT_EQ(finite->GetBinMax(0, bin), itk->GetBinMax(0, bin)) << bin;
  }
}

TEST(VolumeSegmentation, OtsuLeavesNaNAndInfinitiesOut)
{
  // One NaN voxel made ITK's histogram bounds NaN, the threshold NaN and the mask empty
  // ("no voxel is at or above the threshold nan"); infinities stretched the bins over nothing.
  const auto clean = grayscaleVolume();
  const MaskVolume::Pointer expected = segmentVolume(clean, SegmentationOptions{});
  const std::vector<double> expectedThresholds = otsuThresholds(clean, 2);
  for (const float odd : { std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity() })
  {
    SCOPED_TRACE(odd);
    const auto volume = grayscaleVolume();
    volume->SetPixel({ { 0, 0, 0 } }, odd);
    volume->SetPixel({ { 19, 19, 19 } }, odd);
    const MaskVolume::Pointer mask = segmentVolume(volume, SegmentationOptions{});
    // Every voxel but the two changed (the first and the last) as without them.
    for (std::size_t n = 1; n + 1 < volume->GetBufferedRegion().GetNumberOfPixels(); ++n)
      ASSERT_EQ(mask->GetBufferPointer()[n], expected->GetBufferPointer()[n]) << n;
    EXPECT_EQ(otsuThresholds(volume, 2), expectedThresholds);
  }
  // Uniform apart from NaN: nothing to separate.
  auto uniform = makeVolume({ 4, 4, 4 });
  uniform->FillBuffer(3.0f);
  uniform->SetPixel({ { 1, 1, 1 } }, std::numeric_limits<float>::quiet_NaN());
  EXPECT_NE(errorMessageOf(uniform, SegmentationOptions{}).find("every voxel has the same value"), std::string::npos);
  EXPECT_THROW(otsuThresholds(uniform, 1), Error);
}

TEST(VolumeSegmentation, SmoothingDoesNotSpreadNaN)
{
  // A Gaussian spread two NaN voxels (outside a processed MRI's mask, say) over every voxel, and
  // nothing could be thresholded. They are smoothed as background now and stay outside: far from
  // the object, the mask is the clean volume's.
  SegmentationOptions options;
  options.kind = InputKind::Grayscale;
  options.grayscale.method = ThresholdMethod::Manual;
  options.grayscale.threshold = 55.0;
  options.grayscale.denoising.gaussianSigma = 1.0;
  const MaskVolume::Pointer expected = segmentVolume(grayscaleVolume(), options);
  ASSERT_GT(countInside(expected), 500u);
  for (const ProcessingDimension dimension : { ProcessingDimension::Slice2D, ProcessingDimension::Volume3D })
  {
    options.grayscale.dimension = dimension;
    const MaskVolume::Pointer clean = segmentVolume(grayscaleVolume(), options);
    const auto volume = grayscaleVolume();
    volume->SetPixel({ { 0, 0, 0 } }, std::numeric_limits<float>::quiet_NaN());
    volume->SetPixel({ { 19, 19, 19 } }, std::numeric_limits<float>::infinity());
    const MaskVolume::Pointer mask = segmentVolume(volume, options);
    for (std::size_t n = 0; n < volume->GetBufferedRegion().GetNumberOfPixels(); ++n)
      ASSERT_EQ(mask->GetBufferPointer()[n], clean->GetBufferPointer()[n]) << n;
  }
  // A volume without any finite voxel says so.
  auto empty = makeVolume({ 4, 4, 4 });
  empty->FillBuffer(std::numeric_limits<float>::quiet_NaN());
  const std::string message = errorMessageOf(empty, SegmentationOptions{});
  EXPECT_NE(message.find("no voxel has a finite intensity"), std::string::npos) << message;
}

TEST(VolumeSegmentation, NegativeIntegersAreGrayscale)
{
  // CT-like integer values with negatives: not a label map, so Otsu splits air from tissue.
  auto volume = makeVolume({ 10, 10, 10 });
  for (long k = 0; k < 10; ++k)
    for (long j = 0; j < 10; ++j)
      for (long i = 0; i < 10; ++i)
        volume->SetPixel({ { i, j, k } }, i < 4 ? -1000.0f : 40.0f);
  const MaskVolume::Pointer mask = segmentVolume(volume, SegmentationOptions{});
  EXPECT_EQ(countInside(mask), 600u);
}

TEST(VolumeSegmentation, WholeNonNegativeIntensitiesAreGrayscale)
{
  // An MR stored as whole numbers: the noisy volume rounded and kept positive. Its voxels were taken
  // for a label map of about 30 labels, and every non-zero voxel meshed; Otsu now finds the cube.
  auto volume = grayscaleVolume();
  for (float* voxel = volume->GetBufferPointer(); voxel != volume->GetBufferPointer() + 8000; ++voxel)
    *voxel = std::max(1.0f, std::round(*voxel));
  std::string choice;
  const MaskVolume::Pointer mask = segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_EQ(countInside(mask), 1000u);
  EXPECT_EQ(choice.rfind("input kind Grayscale, chosen from the voxels: ", 0), 0u) << choice;
  EXPECT_NE(choice.find("neighbouring non-zero voxels differ in"), std::string::npos) << choice;
  // The same values in blocks (a label map of as many labels, each a slab of voxels) stay labels.
  auto blocks = makeVolume({ 20, 20, 20 });
  for (long k = 0; k < 20; ++k)
    for (long j = 0; j < 20; ++j)
      for (long i = 0; i < 20; ++i)
        blocks->SetPixel({ { i, j, k } }, static_cast<float>(1 + k + 20 * (j / 10)));
  segmentVolume(blocks, SegmentationOptions{}, &choice);
  EXPECT_EQ(choice.rfind("input kind LabelMap, chosen from the voxels: 40 whole", 0), 0u) << choice;
  // Nor a map of 50 separate lesions of two voxels each: their pairs with the background do not count.
  auto lesions = makeVolume({ 20, 20, 20 });
  for (long n = 0; n < 50; ++n)
  {
    const long i = 1 + 4 * (n % 5), j = 1 + 4 * ((n / 5) % 5), k = 1 + 8 * (n / 25);
    lesions->SetPixel({ { i, j, k } }, static_cast<float>(n + 1));
    lesions->SetPixel({ { i, j, k + 1 } }, static_cast<float>(n + 1));
  }
  segmentVolume(lesions, SegmentationOptions{}, &choice);
  EXPECT_EQ(choice.rfind("input kind LabelMap, chosen from the voxels: 51 whole", 0), 0u) << choice;
}

TEST(VolumeSegmentation, LabelsTalliedInRangesAreTheWholeVolumesAndItsFirstBadVoxelIsNamed)
{
  // 256 x 256 x 80 voxels: more than one of the ranges tallied side by side (4 Mi voxels each).
  // Label 3 lies only in the last slices, 70000 (tallied in a set, not the table) only in the
  // first, 12 throughout; each a slab of whole slices, so neighbours are equal.
  auto volume = makeVolume({ 256, 256, 80 });
  float* voxels = volume->GetBufferPointer();
  const std::size_t slice = 256 * 256, count = 80 * slice;
  for (std::size_t n = 0; n < count; ++n)
  {
    const std::size_t k = n / slice;
    voxels[n] = k < 5 ? 70000.0f : k >= 75 ? 3.0f : k % 2 == 0 ? 12.0f : 0.0f;
  }
  std::string choice;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_EQ(choice.rfind("input kind LabelMap, chosen from the voxels: 4 whole non-negative values, 0 to 70000", 0), 0u)
    << choice;
  SegmentationOptions missing;
  missing.label = 7;
  const std::string message = errorMessageOf(volume, missing);
  EXPECT_NE(message.find("3, 12, 70000"), std::string::npos) << message;
  // Two voxels that no label can be, in different ranges: the first in the volume's order is named,
  // whichever range finds its own first.
  const std::size_t early = 1000000, late = 4500000;
  voxels[early] = 0.5f;
  voxels[late] = -1.0f;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_NE(choice.find("a voxel is not a whole number (0.5)"), std::string::npos) << choice;
  voxels[early] = -1.0f;
  voxels[late] = 0.5f;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_NE(choice.find("a voxel is negative (-1)"), std::string::npos) << choice;
  // 65536 values, 0 to 65535: 0 to 39999 in the first range, 40000 to 65535 in runs of ten at the
  // start of the second (the rest 0). The count passes 65535 in the second range, and the account
  // names the value that took it there, the last; a bad voxel after it changes nothing, one before
  // it is named instead.
  const std::size_t second = std::size_t(1) << 22; // the second range's first voxel
  for (std::size_t n = 0; n < count; ++n)
    voxels[n] = n < second                 ? static_cast<float>((n / 100) % 40000)
                : n < second + 10 * 25536 ? static_cast<float>(40000 + (n - second) / 10)
                                           : 0.0f;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_NE(choice.find("more than 65535 distinct values, the last (65535)"), std::string::npos) << choice;
  voxels[second + 10 * 25536 + 10] = -1.0f;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_NE(choice.find("more than 65535 distinct values, the last (65535)"), std::string::npos) << choice;
  voxels[second + 5] = 0.5f;
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_NE(choice.find("a voxel is not a whole number (0.5)"), std::string::npos) << choice;
  // 5000 values of 65536 and over, more than a range's set holds (4096): tallied in order instead,
  // with the same result. Runs of 13 voxels along x, the same in every slice: a label map.
  for (std::size_t n = 0; n < count; ++n)
    voxels[n] = static_cast<float>(70000 + ((n % slice) / 13) % 5000);
  segmentVolume(volume, SegmentationOptions{}, &choice);
  EXPECT_EQ(choice.rfind("input kind LabelMap, chosen from the voxels: 5000 whole non-negative values, 70000 to 74999", 0), 0u)
    << choice;
}

TEST(VolumeSegmentation, AGrayscaleOptionChoosesGrayscale)
{
  // A label map by its voxels (three values), thresholded because a threshold was asked for.
  const auto volume = labelVolume();
  SegmentationOptions options;
  options.threshold = 2.0;
  std::string choice;
  const MaskVolume::Pointer mask = segmentVolume(volume, options, &choice);
  EXPECT_EQ(countInside(mask), 27u + 1u);
  EXPECT_EQ(choice.rfind("input kind Grayscale, chosen from the options: --thresholdMethod Manual", 0), 0u) << choice;
  EXPECT_EQ(grayscaleRequest(SegmentationOptions{}), "");
}

TEST(VolumeSegmentation, ThresholdAboveEveryVoxelIsAnError)
{
  const auto volume = grayscaleVolume();
  SegmentationOptions options;
  options.threshold = 1000.0;
  const std::string message = errorMessageOf(volume, options);
  EXPECT_NE(message.find("threshold 1000"), std::string::npos) << message;
}

TEST(VolumeSegmentation, UniformGrayscaleIsAnError)
{
  auto volume = makeVolume({ 4, 4, 4 });
  volume->FillBuffer(0.5f);
  EXPECT_THROW(segmentVolume(volume, SegmentationOptions{}), Error);
}

TEST(VolumeSegmentation, ForcedGrayscaleThresholdsALabelMap)
{
  const auto volume = labelVolume();
  SegmentationOptions options;
  options.kind = InputKind::Grayscale;
  options.threshold = 2.0;
  const MaskVolume::Pointer mask = segmentVolume(volume, options);
  EXPECT_EQ(countInside(mask), 27u + 1u);
}

} // namespace
} // namespace slicemesh

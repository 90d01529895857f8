// A volume read in the pixel type of its file must give what reading it as float gives: the same
// voxel values and geometry, the same label boxes and masks, the same segmentation.
#include "Core/SliceMeshTypes.h"
#include "LabelIndex.h"
#include "StoredVolume.h"
#include "TemporaryFolderTest.h"
#include "TestVolumes.h"
#include "VolumeReader.h"
#include "VolumeSegmentation.h"

#include "itkImageFileWriter.h"
#include "itkNiftiImageIO.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>

namespace slicemesh
{
namespace
{

namespace fs = std::filesystem;

using Uint8Volume = itk::Image<std::uint8_t, 3>;
using Int16Volume = itk::Image<std::int16_t, 3>;
using Uint16Volume = itk::Image<std::uint16_t, 3>;

class StoredVolumeTest : public testing::TemporaryFolderTest
{
protected:
  StoredVolumeTest()
    : TemporaryFolderTest("slicemesh-stored-")
  {
  }

  template <typename TImage>
  static void write(const TImage* image, const std::string& file, itk::ImageIOBase* io = nullptr)
  {
    auto writer = itk::ImageFileWriter<TImage>::New();
    writer->SetInput(image);
    writer->SetFileName(file);
    if (io)
      writer->SetImageIO(io);
    writer->Update();
  }

  /** A 12 x 10 x 6 image, oblique and anisotropic, whose voxel (i, j, k) is value(i, j, k). */
  template <typename TImage, typename Value>
  static typename TImage::Pointer image(Value value)
  {
    auto volume = testing::makeImage<TImage>({ 12, 10, 6 }, { 0.7, 0.9, 2.5 });
    typename TImage::PointType origin;
    origin[0] = -20.0, origin[1] = 4.5, origin[2] = 31.0;
    volume->SetOrigin(origin);
    typename TImage::DirectionType direction;
    direction.Fill(0.0);
    direction[0][1] = 1.0, direction[1][0] = -1.0, direction[2][2] = 1.0;
    volume->SetDirection(direction);
    for (long k = 0; k < 6; ++k)
      for (long j = 0; j < 10; ++j)
        for (long i = 0; i < 12; ++i)
          testing::setVoxel(volume.GetPointer(), i, j, k, static_cast<typename TImage::PixelType>(value(i, j, k)));
    return volume;
  }

  /** Labels above one byte in boxes of their own: 300, 1000 and 40000 on a background of 0. */
  static Uint16Volume::Pointer wideLabels()
  {
    return image<Uint16Volume>(
      [](long i, long j, long k) -> int
      {
        if (i >= 1 && i < 5 && j >= 2 && j < 8 && k >= 1 && k < 4)
          return 300;
        if (i >= 6 && i < 11 && j >= 1 && j < 4 && k >= 2 && k < 6)
          return 1000;
        if (i >= 7 && i < 10 && j >= 6 && j < 9 && k < 3)
          return 40000;
        return 0;
      });
  }
};

template <typename TImage>
void expectSameImage(const itk::ImageBase<3>* stored, const ScalarVolume* asFloat)
{
  const auto* image = dynamic_cast<const TImage*>(stored);
  ASSERT_NE(image, nullptr) << "not read in the file's pixel type";
  ASSERT_EQ(image->GetBufferedRegion(), asFloat->GetBufferedRegion());
  EXPECT_EQ(image->GetOrigin(), asFloat->GetOrigin());
  EXPECT_EQ(image->GetSpacing(), asFloat->GetSpacing());
  EXPECT_EQ(image->GetDirection(), asFloat->GetDirection());
  const std::size_t count = image->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t n = 0; n < count; ++n)
    ASSERT_EQ(static_cast<float>(image->GetBufferPointer()[n]), asFloat->GetBufferPointer()[n]) << "voxel " << n;
}

bool sameMask(const MaskVolume* a, const MaskVolume* b)
{
  if (a->GetBufferedRegion() != b->GetBufferedRegion() || a->GetOrigin() != b->GetOrigin() ||
      a->GetSpacing() != b->GetSpacing() || a->GetDirection() != b->GetDirection())
    return false;
  const std::size_t count = a->GetBufferedRegion().GetNumberOfPixels();
  return std::equal(a->GetBufferPointer(), a->GetBufferPointer() + count, b->GetBufferPointer());
}

TEST_F(StoredVolumeTest, IntegersAreReadInTheFilesPixelTypeWithTheValuesOfFloat)
{
  const auto bytes = image<Uint8Volume>([](long i, long j, long k) { return (i + 3 * j + 7 * k) % 256; });
  const auto shorts = image<Int16Volume>([](long i, long j, long k) { return 400 * i - 900 * j + 17 * k - 1000; });
  const auto labels = wideLabels();
  for (const std::string extension : { ".nrrd", ".nii.gz", ".mha" })
  {
    SCOPED_TRACE(extension);
    write(bytes.GetPointer(), path("bytes" + extension));
    write(shorts.GetPointer(), path("shorts" + extension));
    write(labels.GetPointer(), path("labels" + extension));
    const StoredVolume storedBytes = readStoredVolume(path("bytes" + extension));
    const StoredVolume storedShorts = readStoredVolume(path("shorts" + extension));
    const StoredVolume storedLabels = readStoredVolume(path("labels" + extension));
    expectSameImage<Uint8Volume>(imageOf(storedBytes), readVolume(path("bytes" + extension)));
    expectSameImage<Int16Volume>(imageOf(storedShorts), readVolume(path("shorts" + extension)));
    expectSameImage<Uint16Volume>(imageOf(storedLabels), readVolume(path("labels" + extension)));
    // Widened, they are the float volume itself.
    expectSameImage<ScalarVolume>(floatVolumeOf(storedShorts), readVolume(path("shorts" + extension)));
  }
  // Float stays float.
  const auto reals = image<ScalarVolume>([](long i, long j, long k) { return 0.25 * i - j + 0.5 * k; });
  write(reals.GetPointer(), path("reals.nrrd"));
  expectSameImage<ScalarVolume>(imageOf(readStoredVolume(path("reals.nrrd"))), readVolume(path("reals.nrrd")));
}

TEST_F(StoredVolumeTest, NiftiWithScalingIsReadWithItsScaledValues)
{
  // scl_slope and scl_inter turn stored integers into other numbers: what is read must be those
  // (ITK reports such a file as float, so it is read as float).
  const auto shorts = image<Int16Volume>([](long i, long j, long k) { return i + 10 * j + 100 * k; });
  auto io = itk::NiftiImageIO::New();
  io->SetRescaleSlope(0.5);
  io->SetRescaleIntercept(3.0);
  write(shorts.GetPointer(), path("scaled.nii.gz"), io);
  const ScalarVolume::Pointer asFloat = readVolume(path("scaled.nii.gz"));
  EXPECT_EQ(asFloat->GetPixel({ { 1, 0, 0 } }), 3.5f);
  const StoredVolume stored = readStoredVolume(path("scaled.nii.gz"));
  expectSameImage<ScalarVolume>(floatVolumeOf(stored), asFloat);
}

TEST_F(StoredVolumeTest, LabelsAboveOneByteGiveTheBoxesAndMasksOfFloat)
{
  write(wideLabels().GetPointer(), path("labels.nrrd"));
  const StoredVolume stored = readStoredVolume(path("labels.nrrd"));
  const auto* labelMap = std::get<Uint16Volume::Pointer>(stored).GetPointer();
  const ScalarVolume::Pointer asFloat = readVolume(path("labels.nrrd"));

  const std::vector<LabelExtent> extents = indexLabels(labelMap);
  const std::vector<LabelExtent> floatExtents = indexLabels(asFloat);
  ASSERT_EQ(extents.size(), 3u);
  ASSERT_EQ(floatExtents.size(), 3u);
  const int expectedLabels[] = { 300, 1000, 40000 };
  const std::size_t expectedVoxels[] = { 4 * 6 * 3, 5 * 3 * 4, 3 * 3 * 3 };
  for (std::size_t n = 0; n < extents.size(); ++n)
  {
    SCOPED_TRACE(extents[n].label);
    EXPECT_EQ(extents[n].label, expectedLabels[n]);
    EXPECT_EQ(extents[n].voxels, expectedVoxels[n]);
    EXPECT_EQ(extents[n].label, floatExtents[n].label);
    EXPECT_EQ(extents[n].voxels, floatExtents[n].voxels);
    EXPECT_EQ(extents[n].lower, floatExtents[n].lower);
    EXPECT_EQ(extents[n].upper, floatExtents[n].upper);
    const MaskVolume::Pointer mask = cropLabelMask(labelMap, extents[n]);
    EXPECT_TRUE(sameMask(mask, cropLabelMask(asFloat, floatExtents[n])));
    std::size_t inside = 0;
    for (std::size_t v = 0; v < mask->GetBufferedRegion().GetNumberOfPixels(); ++v)
      inside += mask->GetBufferPointer()[v];
    EXPECT_EQ(inside, expectedVoxels[n]);
  }
  EXPECT_EQ(extents[1].lower, (std::array<long, 3>{ 6, 1, 2 }));
  EXPECT_EQ(extents[1].upper, (std::array<long, 3>{ 10, 3, 5 }));
}

TEST_F(StoredVolumeTest, NegativeLabelsAreIndexedOnlyWhenAllowed)
{
  // A signed label map: -5000 and -5 (below the table of small labels), 3, and 5000 (beyond it).
  write(image<Int16Volume>(
          [](long i, long j, long k) -> int
          {
            if (k >= 4)
              return 0;
            return i < 3 ? -5000 : i < 6 ? -5 : i < 9 ? 3 : j < 5 ? 5000 : 0;
          })
          .GetPointer(),
        path("signed.nrrd"));
  const StoredVolume stored = readStoredVolume(path("signed.nrrd"));
  const auto* labelMap = std::get<Int16Volume::Pointer>(stored).GetPointer();
  const ScalarVolume::Pointer asFloat = readVolume(path("signed.nrrd"));

  // Refused, a negative voxel is named (a CT's values are no labels).
  for (const auto& index : { std::function<void()>([&] { indexLabels(labelMap); }),
                             std::function<void()>([&] { indexLabels(asFloat); }) })
  {
    try
    {
      index();
      ADD_FAILURE() << "a negative voxel was taken for a label";
    }
    catch (const Error& e)
    {
      EXPECT_STREQ(e.what(), "voxel (0, 0, 0) holds -5000: a negative value, which is a label only in a volume given "
                             "with --inputKind LabelMap");
    }
  }
  // Allowed, they are labels in increasing order, with their boxes, from the stored or float volume.
  const std::vector<LabelExtent> extents = indexLabels(labelMap, NegativeLabels::Allowed);
  const std::vector<LabelExtent> floatExtents = indexLabels(asFloat, NegativeLabels::Allowed);
  ASSERT_EQ(extents.size(), 4u);
  ASSERT_EQ(floatExtents.size(), 4u);
  const int expectedLabels[] = { -5000, -5, 3, 5000 };
  const std::size_t expectedVoxels[] = { 3 * 10 * 4, 3 * 10 * 4, 3 * 10 * 4, 3 * 5 * 4 };
  for (std::size_t n = 0; n < extents.size(); ++n)
  {
    SCOPED_TRACE(expectedLabels[n]);
    EXPECT_EQ(extents[n].label, expectedLabels[n]);
    EXPECT_EQ(extents[n].voxels, expectedVoxels[n]);
    EXPECT_EQ(floatExtents[n].label, expectedLabels[n]);
    EXPECT_EQ(floatExtents[n].voxels, expectedVoxels[n]);
    EXPECT_TRUE(sameMask(cropLabelMask(labelMap, extents[n]), cropLabelMask(asFloat, floatExtents[n])));
  }
  EXPECT_EQ(extents[1].lower, (std::array<long, 3>{ 3, 0, 0 }));
  EXPECT_EQ(extents[1].upper, (std::array<long, 3>{ 5, 9, 3 }));
}

TEST_F(StoredVolumeTest, SegmentationIsTheMaskOfTheFloatVolume)
{
  write(wideLabels().GetPointer(), path("labels.nrrd"));
  // Negative values: grayscale, segmented by Otsu's threshold after widening.
  write(image<Int16Volume>([](long i, long j, long) { return i < 6 ? -500 + j : 700 - j; }).GetPointer(),
        path("grayscale.nii.gz"));
  for (const std::string name : { "labels.nrrd", "grayscale.nii.gz" })
  {
    SCOPED_TRACE(name);
    for (const std::optional<int> label : { std::optional<int>(), std::optional<int>(1000) })
    {
      SegmentationOptions options;
      if (name == "labels.nrrd")
        options.label = label;
      const MaskVolume::Pointer fromFloat = segmentVolume(readVolume(path(name)), options);
      const MaskVolume::Pointer fromStored = segmentStoredVolume(readStoredVolume(path(name)), options);
      EXPECT_TRUE(sameMask(fromStored, fromFloat));
    }
  }
  // A label that is absent is named as on float.
  SegmentationOptions absent;
  absent.label = 7;
  std::string floatMessage, storedMessage;
  try
  {
    segmentVolume(readVolume(path("labels.nrrd")), absent);
  }
  catch (const Error& e)
  {
    floatMessage = e.what();
  }
  try
  {
    segmentStoredVolume(readStoredVolume(path("labels.nrrd")), absent);
  }
  catch (const Error& e)
  {
    storedMessage = e.what();
  }
  EXPECT_NE(floatMessage.find("labels present: 300, 1000, 40000"), std::string::npos) << floatMessage;
  EXPECT_EQ(storedMessage, floatMessage);
}

TEST_F(StoredVolumeTest, MemoryEstimateCountsTheVolumeAsItIsHeld)
{
  // 4 M voxels: 64 MiB + 4 M x (1 + 9) bytes = 102 MiB as stored bytes; as float, 64 MiB + 4 M x
  // (4 + 1 + 9) bytes = 117 MiB. Under a limit of 108 MiB the label map of bytes is read as stored,
  // and refused as float.
  auto bytes = testing::makeImage<Uint8Volume>({ 200, 200, 100 });
  bytes->FillBuffer(1);
  write(bytes.GetPointer(), path("large.nrrd"));
  const char* previous = std::getenv("SLICEMESH_MEMORY_LIMIT_MB");
  const std::string saved = previous ? previous : "";
  ::setenv("SLICEMESH_MEMORY_LIMIT_MB", "108", 1);
  EXPECT_NO_THROW(readStoredVolume(path("large.nrrd")));
  std::string refused;
  try
  {
    readVolume(path("large.nrrd"));
  }
  catch (const Error& e)
  {
    refused = e.what();
  }
  if (previous)
    ::setenv("SLICEMESH_MEMORY_LIMIT_MB", saved.c_str(), 1);
  else
    ::unsetenv("SLICEMESH_MEMORY_LIMIT_MB");
  EXPECT_NE(refused.find("200 x 200 x 100 volume needs about"), std::string::npos) << refused;
}

} // namespace
} // namespace slicemesh

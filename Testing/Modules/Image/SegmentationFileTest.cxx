// Reading segmentation files: 3D Slicer's .seg.nrrd (one and two layers, the fields of older
// Slicers, fractional labelmaps) and DICOM SEG (binary and fractional), written by the test:
// segments, names, colours, layers, and voxels in the physical place they were written at.
#include "SegmentationFile.h"
#include "SegmentationFileWriters.h"

#include "Core/SliceMeshTypes.h"
#include "TemporaryFolderTest.h"
#include "TestVolumes.h"

#include "itkImageFileWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace slicemesh
{
namespace
{

namespace fs = std::filesystem;
using testing::ImageGrid;
using testing::PhysicalPoint;

class SegmentationFileTest : public testing::TemporaryFolderTest
{
protected:
  SegmentationFileTest()
    : TemporaryFolderTest("slicemesh-segfile-")
  {
  }
};

double distance(const PhysicalPoint& a, const PhysicalPoint& b)
{
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/** A mirrored grid (the first axis points to the patient's right) with anisotropic voxels. */
ImageGrid mirroredGrid()
{
  ImageGrid grid;
  grid.size = { 12, 10, 8 };
  grid.spacing = { 0.8, 0.9, 1.5 };
  grid.origin = { 30.0, -12.0, 4.0 };
  grid.axes = { { { -1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  return grid;
}

/** An oblique grid: rotated 30 degrees about z, then 20 degrees about the new x axis. */
ImageGrid obliqueGrid()
{
  ImageGrid grid;
  grid.size = { 14, 12, 9 };
  grid.spacing = { 0.7, 0.9, 1.25 };
  grid.origin = { -20.0, 15.0, -40.0 };
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6), ct = std::cos(M_PI / 9), st = std::sin(M_PI / 9);
  grid.axes = { { { c, s, 0 }, { -s * ct, c * ct, st }, { s * st, -c * st, ct } } };
  return grid;
}

/** The voxel value of `volume` at the physical point (which must be a voxel centre), or -1 outside. */
float valueAt(const ScalarVolume* volume, const PhysicalPoint& p)
{
  ScalarVolume::PointType point;
  for (int a = 0; a < 3; ++a)
    point[a] = p[a];
  ScalarVolume::IndexType index;
  if (!volume->TransformPhysicalPointToIndex(point, index))
    return -1.0f;
  return volume->GetPixel(index);
}

TEST_F(SegmentationFileTest, SlicerTwoLayersGiveSegmentsWithNamesColoursLayersAndPlacedVoxels)
{
  const ImageGrid grid = mirroredGrid();
  // Layer 0: value 1 on the voxels with i < 4, value 2 on j >= 7 (with i >= 4); layer 1: value 1 on
  // i in [2, 6) (overlapping both).
  const PhysicalPoint o = grid.origin;
  auto indexOf = [&](const PhysicalPoint& p, int axis)
  {
    double t = 0;
    for (int a = 0; a < 3; ++a)
      t += (p[a] - o[a]) * grid.axes[axis][a];
    return static_cast<int>(std::lround(t / grid.spacing[axis]));
  };
  testing::writeSlicerSegmentation(
    path("two.seg.nrrd"), grid,
    { [&](const PhysicalPoint& p) -> unsigned char { return indexOf(p, 0) < 4 ? 1 : indexOf(p, 1) >= 7 ? 2 : 0; },
      [&](const PhysicalPoint& p) -> unsigned char { return indexOf(p, 0) >= 2 && indexOf(p, 0) < 6 ? 1 : 0; } },
    { { "Segment_1", "Liver", "0.9 0.2 0.1", "0", "1" },
      { "Segment_2", "Kidney", "0 0.5 1", "0", "2" },
      { "Segment_3", "Tumor", "1 1 0", "1", "1" } });

  ASSERT_EQ(segmentationFormatOf(path("two.seg.nrrd")), SegmentationFormat::SlicerNrrd);
  const SegmentationFile file = readSegmentationFile(path("two.seg.nrrd"));
  ASSERT_EQ(file.layers.size(), 2u);
  ASSERT_EQ(file.segments.size(), 3u);
  const std::array<std::string, 3> names{ "Liver", "Kidney", "Tumor" };
  const std::array<std::array<unsigned char, 3>, 3> colours{ { { 230, 51, 26 }, { 0, 128, 255 }, { 255, 255, 0 } } };
  const std::array<std::size_t, 3> layers{ 0, 0, 1 };
  const std::array<int, 3> values{ 1, 2, 1 };
  for (std::size_t n = 0; n < 3; ++n)
  {
    const SegmentationFile::Segment& s = file.segments[n];
    EXPECT_EQ(s.number, static_cast<int>(n) + 1);
    EXPECT_EQ(s.id, "Segment_" + std::to_string(n + 1));
    EXPECT_EQ(s.name, names[n]);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(s.rgba[c], colours[n][c]) << names[n] << " component " << c;
    EXPECT_EQ(s.layer, layers[n]) << names[n];
    EXPECT_EQ(s.labelValue, values[n]) << names[n];
  }
  // Each layer has the file's geometry, and the voxel written at a point is read at that point.
  for (const ScalarVolume::Pointer& layer : file.layers)
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(layer->GetOrigin()[a], grid.origin[a], 1e-9);
      EXPECT_NEAR(layer->GetSpacing()[a], grid.spacing[a], 1e-9);
      for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(layer->GetDirection()[a][b], grid.axes[b][a], 1e-9);
    }
  }
  EXPECT_EQ(valueAt(file.layers[0], grid.point(3, 8, 2)), 1.0f);
  EXPECT_EQ(valueAt(file.layers[0], grid.point(4, 8, 2)), 2.0f);
  EXPECT_EQ(valueAt(file.layers[0], grid.point(4, 6, 2)), 0.0f);
  EXPECT_EQ(valueAt(file.layers[1], grid.point(3, 8, 2)), 1.0f); // overlaps Liver there
  EXPECT_EQ(valueAt(file.layers[1], grid.point(6, 8, 2)), 0.0f);
}

TEST_F(SegmentationFileTest, SlicerFileWithoutLayerFieldsHasALayerPerSegmentAndDefaults)
{
  // As Slicer before 4.11 wrote overlapping segments: one layer each, value 1, no _Layer or
  // _LabelValue; no colour either (a generated one), no name (the ID instead).
  const ImageGrid grid = mirroredGrid();
  testing::writeSlicerSegmentation(path("old.seg.nrrd"), grid,
                                   { [](const PhysicalPoint&) -> unsigned char { return 1; },
                                     [](const PhysicalPoint& p) -> unsigned char { return p[2] > 8.0 ? 1 : 0; } },
                                   { { "Skin", "Skin", "0.5 0.5 0.5", "", "" }, { "Bone", "", "", "", "" } });
  const SegmentationFile file = readSlicerSegmentation(path("old.seg.nrrd"));
  ASSERT_EQ(file.segments.size(), 2u);
  EXPECT_EQ(file.segments[0].layer, 0u);
  EXPECT_EQ(file.segments[1].layer, 1u);
  EXPECT_EQ(file.segments[0].labelValue, 1);
  EXPECT_EQ(file.segments[1].labelValue, 1);
  EXPECT_EQ(file.segments[1].name, "Bone");
  EXPECT_EQ(file.segments[0].rgba[0], 128);
}

TEST_F(SegmentationFileTest, SlicerSingleLayerFileIsThreeDimensional)
{
  const ImageGrid grid = mirroredGrid();
  testing::writeSlicerSegmentation(path("one.seg.nrrd"), grid,
                                   { [](const PhysicalPoint& p) -> unsigned char { return p[2] > 8.0 ? 3 : 0; } },
                                   { { "Segment_1", "Heart", "1 0 0", "0", "3" } });
  const SegmentationFile file = readSegmentationFile(path("one.seg.nrrd"));
  ASSERT_EQ(file.layers.size(), 1u);
  ASSERT_EQ(file.segments.size(), 1u);
  EXPECT_EQ(file.segments[0].labelValue, 3);
  EXPECT_EQ(valueAt(file.layers[0], grid.point(0, 0, 7)), 3.0f);
}

TEST_F(SegmentationFileTest, SlicerFieldsThatContradictTheImageAreErrors)
{
  const ImageGrid grid = mirroredGrid();
  auto write = [&](const std::string& name, const testing::SlicerSegmentSpec& segment,
                   const std::vector<std::string>& extra = {})
  {
    testing::writeSlicerSegmentation(path(name), grid, { [](const PhysicalPoint&) -> unsigned char { return 1; } },
                                     { segment }, extra);
    return path(name);
  };
  EXPECT_THROW(readSlicerSegmentation(write("layer.seg.nrrd", { "a", "A", "1 0 0", "2", "1" })), Error);
  EXPECT_THROW(readSlicerSegmentation(write("value.seg.nrrd", { "a", "A", "1 0 0", "0", "one" })), Error);
  EXPECT_THROW(readSlicerSegmentation(write("colour.seg.nrrd", { "a", "A", "red", "0", "1" })), Error);
  EXPECT_THROW(readSlicerSegmentation(write("contour.seg.nrrd", { "a", "A", "1 0 0", "0", "1" },
                                            { "Segmentation_MasterRepresentation:=Planar contour" })),
               Error);
  // A truncated file: the header promises more voxels than there are.
  const std::string whole = write("whole.seg.nrrd", { "a", "A", "1 0 0", "0", "1" });
  fs::resize_file(whole, fs::file_size(whole) - 300);
  try
  {
    readSegmentationFile(whole);
    ADD_FAILURE() << "a truncated .seg.nrrd was read";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(whole), std::string::npos) << e.what();
  }
}

/** The index of the voxel centred at p along `axis` of the grid. */
int indexAlong(const ImageGrid& grid, const PhysicalPoint& p, int axis)
{
  double t = 0;
  for (int a = 0; a < 3; ++a)
    t += (p[a] - grid.origin[a]) * grid.axes[axis][a];
  return static_cast<int>(std::lround(t / grid.spacing[axis]));
}

TEST_F(SegmentationFileTest, SlicerFractionalLayersBecomeLabelMapsFromHalfTheRangeWithinTheExtent)
{
  const ImageGrid grid = mirroredGrid();
  // As Slicer writes a fractional labelmap: signed char, a layer per segment, no scalar range (so
  // -108..108, half at 0). Layer 0 ramps along i: value i - 6, so i = 5 (-1) is out and i = 6 (0)
  // in. Layer 1 is full (108) on j >= 5 and empty (-108) below, within its extent (i 2..8, k 1..6);
  // outside it Slicer pads with 0, half full but not the segment's. Layer 2 is an empty segment as
  // Slicer writes one: all 0, extent "0 -1 0 -1 0 -1".
  testing::writeSlicerFractionalSegmentation(
    path("fractional.seg.nrrd"), grid,
    { [&](const PhysicalPoint& p) { return indexAlong(grid, p, 0) - 6; },
      [&](const PhysicalPoint& p)
      {
        const int i = indexAlong(grid, p, 0), j = indexAlong(grid, p, 1), k = indexAlong(grid, p, 2);
        if (i < 2 || i > 8 || k < 1 || k > 6)
          return 0;
        return j >= 5 ? 108 : -108;
      },
      [](const PhysicalPoint&) { return 0; } },
    { { "Segment_1", "Ramp", "0.9 0.2 0.1", "0", "1", "0 11 0 9 0 7" },
      { "Segment_2", "Slab", "0 0.5 1", "1", "1", "2 8 0 9 1 6" },
      { "Segment_3", "Nothing", "1 1 0", "2", "1", "0 -1 0 -1 0 -1" } });

  ASSERT_EQ(segmentationFormatOf(path("fractional.seg.nrrd")), SegmentationFormat::SlicerNrrd);
  const SegmentationFile file = readSegmentationFile(path("fractional.seg.nrrd"));
  ASSERT_EQ(file.layers.size(), 3u);
  ASSERT_EQ(file.segments.size(), 3u);
  const std::array<std::string, 3> names{ "Ramp", "Slab", "Nothing" };
  for (std::size_t n = 0; n < 3; ++n)
  {
    EXPECT_EQ(file.segments[n].name, names[n]);
    EXPECT_EQ(file.segments[n].layer, n);
    EXPECT_EQ(file.segments[n].labelValue, 1);
  }
  EXPECT_EQ(file.segments[1].rgba[2], 255);
  for (int k = 0; k < grid.size[2]; ++k)
    for (int j = 0; j < grid.size[1]; ++j)
      for (int i = 0; i < grid.size[0]; ++i)
      {
        const PhysicalPoint p = grid.point(i, j, k);
        EXPECT_EQ(valueAt(file.layers[0], p), i >= 6 ? 1.0f : 0.0f) << i << " " << j << " " << k;
        const bool inSlab = i >= 2 && i <= 8 && k >= 1 && k <= 6 && j >= 5;
        EXPECT_EQ(valueAt(file.layers[1], p), inSlab ? 1.0f : 0.0f) << i << " " << j << " " << k;
        EXPECT_EQ(valueAt(file.layers[2], p), 0.0f) << i << " " << j << " " << k;
      }
}

TEST_F(SegmentationFileTest, SlicerFractionalRangeFromTheHeaderSetsTheHalf)
{
  // Unsigned char fractions from 0 to 216 (the other scale Slicer's code knows), with the range in
  // the header: half is 108, so i * 30 is in from i = 4 (120) and out at 3 (90). Without the range
  // the scale of unsigned char voxels is unknown: an error.
  ImageGrid grid;
  grid.size = { 8, 3, 2 };
  auto write = [&](const std::string& name, const std::vector<std::string>& extra)
  {
    testing::writeSlicerFractionalSegmentation(path(name), grid,
                                               { [](const PhysicalPoint& p) { return static_cast<int>(p[0]) * 30; } },
                                               { { "Segment_1", "Ramp", "1 0 0", "0", "1" } }, extra, false,
                                               "unsigned char");
    return path(name);
  };
  const SegmentationFile file = readSlicerSegmentation(write("ranged.seg.nrrd", { "Segment0_ScalarRange:=0 216" }));
  ASSERT_EQ(file.layers.size(), 1u);
  for (int i = 0; i < grid.size[0]; ++i)
    EXPECT_EQ(valueAt(file.layers[0], grid.point(i, 1, 1)), i >= 4 ? 1.0f : 0.0f) << i;
  try
  {
    readSlicerSegmentation(write("unranged.seg.nrrd", {}));
    ADD_FAILURE() << "a fractional labelmap of unsigned char without a range was read";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("a fractional labelmap of unsigned char voxels without SegmentN_ScalarRange"),
              std::string::npos)
      << e.what();
  }
}

TEST_F(SegmentationFileTest, SlicerFractionalLayoutsThatCannotBeReadAreErrors)
{
  const ImageGrid grid = mirroredGrid();
  auto message = [&](const std::string& name, const std::vector<std::function<int(const PhysicalPoint&)>>& layers,
                     const std::vector<testing::SlicerSegmentSpec>& segments,
                     const std::vector<std::string>& extra = {})
  {
    testing::writeSlicerFractionalSegmentation(path(name), grid, layers, segments, extra);
    try
    {
      readSegmentationFile(path(name));
    }
    catch (const Error& e)
    {
      const std::string text = e.what();
      EXPECT_EQ(text.find('\n'), std::string::npos) << text;
      EXPECT_NE(text.find(path(name)), std::string::npos) << text;
      return text;
    }
    return std::string("read without an error");
  };
  const auto half = [](const PhysicalPoint&) { return 0; };
  // Two segments in one layer: a fractional layer holds one segment's fractions.
  EXPECT_NE(message("shared.seg.nrrd", { half }, { { "a", "A", "1 0 0", "0", "1" }, { "b", "B", "0 1 0", "0", "2" } })
              .find("Segment1 is in layer 0 with Segment0; a fractional labelmap has a layer of its own for each segment"),
            std::string::npos);
  // A voxel above the range: not Slicer's -108..108 scale.
  EXPECT_NE(message("over.seg.nrrd", { [](const PhysicalPoint& p) { return p[2] > 10.0 ? 120 : 0; } },
                    { { "a", "A", "1 0 0", "0", "1" } })
              .find("Segment0: voxel (0, 0, 5) is 120, outside the fractional range -108 to 108"),
            std::string::npos);
  // Fields that are not a range or an extent.
  EXPECT_NE(message("range.seg.nrrd", { half }, { { "a", "A", "1 0 0", "0", "1" } }, { "Segment0_ScalarRange:=1 0" })
              .find("header field Segment0_ScalarRange is '1 0', not a range of fractions"),
            std::string::npos);
  EXPECT_NE(message("extent.seg.nrrd", { half }, { { "a", "A", "1 0 0", "0", "1", "0 3 0 3" } })
              .find("header field Segment0_Extent is '0 3 0 3', not six integers"),
            std::string::npos);
}

TEST_F(SegmentationFileTest, OrdinaryVolumesAreNotSegmentationFiles)
{
  auto volume = testing::makeVolume({ 4, 4, 4 }, { 1.0, 1.0, 1.0 });
  auto writer = itk::ImageFileWriter<ScalarVolume>::New();
  for (const std::string name : { "plain.nrrd", "plain.mha", "plain.nii.gz" })
  {
    writer->SetInput(volume);
    writer->SetFileName(path(name));
    writer->Update();
    EXPECT_EQ(segmentationFormatOf(path(name)), SegmentationFormat::None) << name;
  }
  EXPECT_EQ(segmentationFormatOf(path("missing.seg.nrrd")), SegmentationFormat::None);
  EXPECT_THROW(readSegmentationFile(path("plain.nrrd")), Error);
}

/** A ball of radius 3 mm around `centre`, as the fraction of a pixel inside (0 or 1). */
std::function<double(const PhysicalPoint&)> ball(const PhysicalPoint& centre, double radius)
{
  return [=](const PhysicalPoint& p) { return distance(p, centre) <= radius ? 1.0 : 0.0; };
}

TEST_F(SegmentationFileTest, DicomSegFramesLandWhereTheyWereWrittenOnAnObliqueGrid)
{
  const ImageGrid grid = obliqueGrid();
  const PhysicalPoint centreA = grid.point(5, 5, 4), centreB = grid.point(8, 6, 5);
  testing::writeDicomSegmentation(path("seg.dcm"), grid,
                                  { { "Prostate", { 0.8, 0.3, 0.2 }, ball(centreA, 3.0) },
                                    { "Lesion", { 0.1, 0.7, 0.2 }, ball(centreB, 2.5) },
                                    { "Nothing", { 0.5, 0.5, 0.5 }, [](const PhysicalPoint&) { return 0.0; } } });
  ASSERT_EQ(segmentationFormatOf(path("seg.dcm")), SegmentationFormat::DicomSeg);
  const SegmentationFile file = readSegmentationFile(path("seg.dcm"));
  ASSERT_EQ(file.segments.size(), 3u);
  ASSERT_EQ(file.layers.size(), 3u);
  EXPECT_EQ(file.segments[0].name, "Prostate");
  EXPECT_EQ(file.segments[1].name, "Lesion");
  EXPECT_EQ(file.segments[1].number, 2);
  // The colour goes through CIELab and back: within one step of the RGB written.
  const std::array<double, 3> rgb{ 0.8, 0.3, 0.2 };
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(file.segments[0].rgba[c], rgb[c] * 255.0, 1.0) << c;

  // Every voxel centre of the grid: inside the ball exactly where the file's layer says so.
  for (int s = 0; s < 2; ++s)
  {
    const ScalarVolume* layer = file.layers[s];
    const PhysicalPoint centre = s == 0 ? centreA : centreB;
    const double radius = s == 0 ? 3.0 : 2.5;
    std::size_t inside = 0;
    for (int k = 0; k < grid.size[2]; ++k)
      for (int j = 0; j < grid.size[1]; ++j)
        for (int i = 0; i < grid.size[0]; ++i)
        {
          const PhysicalPoint p = grid.point(i, j, k);
          const bool expected = distance(p, centre) <= radius;
          const float value = valueAt(layer, p);
          // Outside the layer's slices the segment has no voxel.
          EXPECT_EQ(value == 1.0f, expected) << "segment " << s + 1 << " voxel " << i << " " << j << " " << k;
          inside += expected;
        }
    EXPECT_GT(inside, 20u);
    // The layer covers only the slices with frames.
    EXPECT_LT(layer->GetLargestPossibleRegion().GetSize()[2], static_cast<std::size_t>(grid.size[2]));
  }
  EXPECT_EQ(file.layers[2]->GetLargestPossibleRegion().GetNumberOfPixels(), 1u);
  EXPECT_EQ(file.layers[2]->GetBufferPointer()[0], 0.0f);
}

TEST_F(SegmentationFileTest, DicomSegSegmentsNumberedOtherwiseThanFromOneKeepTheirNumbers)
{
  // Segments numbered 3 and 7 (the standard numbers them 1, 2, ...; DCMTK counts them by position):
  // refused as "frame 1 refers to segment 3, which does not exist". Each keeps its number now.
  const ImageGrid grid = obliqueGrid();
  const PhysicalPoint centreA = grid.point(5, 5, 4), centreB = grid.point(8, 6, 5);
  testing::writeDicomSegmentation(path("seg.dcm"), grid,
                                  { { "Prostate", { 0.8, 0.3, 0.2 }, ball(centreA, 3.0) },
                                    { "Lesion", { 0.1, 0.7, 0.2 }, ball(centreB, 2.5) } });
  testing::renumberDicomSegments(path("seg.dcm"), { 3, 7 });
  const SegmentationFile file = readSegmentationFile(path("seg.dcm"));
  ASSERT_EQ(file.segments.size(), 2u);
  EXPECT_EQ(file.segments[0].number, 3);
  EXPECT_EQ(file.segments[1].number, 7);
  EXPECT_EQ(file.segments[1].name, "Lesion");
  // Each segment's frames in its own layer, voxel by voxel.
  for (int s = 0; s < 2; ++s)
    for (int k = 0; k < grid.size[2]; ++k)
      for (int j = 0; j < grid.size[1]; ++j)
        for (int i = 0; i < grid.size[0]; ++i)
        {
          const PhysicalPoint p = grid.point(i, j, k);
          const bool expected = s == 0 ? distance(p, centreA) <= 3.0 : distance(p, centreB) <= 2.5;
          EXPECT_EQ(valueAt(file.layers[s], p) == 1.0f, expected) << "segment " << s << " voxel " << i << " " << j << " " << k;
        }
}

/** Whether pixel (i, j, k) is in the pattern of the test of frames that start mid-byte: a ball off
 *  the centre and a scatter of lone pixels that moves from slice to slice, so that a bit read from
 *  another place of the frame, or from the next one, shows. */
bool lopsidedPattern(int i, int j, int k)
{
  const bool ball = std::hypot(i - 3.0, j - 7.0, k - 4.5) <= 4.0;
  return ball || (7 * i + 3 * j + 5 * k) % 11 == 0;
}

TEST_F(SegmentationFileTest, DicomSegBinaryFramesThatStartMidByteAreReadBitForBit)
{
  // 13 x 11 pixels: 143 bits a frame. The frames of a BINARY file are one bit stream, so frame k
  // starts at bit 143 k: at every bit position of a byte (0, 7, 6, ..., 1) over the first eight.
  ImageGrid grid;
  grid.size = { 13, 11, 10 };
  auto index = [](double x) { return static_cast<int>(std::lround(x)); };
  testing::writeDicomSegmentation(path("odd.dcm"), grid,
                                  { { "Pattern", { 1, 0, 0 }, [&](const PhysicalPoint& p)
                                      { return lopsidedPattern(index(p[0]), index(p[1]), index(p[2])) ? 1.0 : 0.0; } } });
  const SegmentationFile file = readDicomSegmentation(path("odd.dcm"));
  ASSERT_EQ(file.layers.size(), 1u);
  std::size_t wrong = 0;
  for (int k = 0; k < grid.size[2]; ++k)
    for (int j = 0; j < grid.size[1]; ++j)
      for (int i = 0; i < grid.size[0]; ++i)
      {
        const bool expected = lopsidedPattern(i, j, k);
        const float value = valueAt(file.layers[0], grid.point(i, j, k));
        if ((value == 1.0f) != expected && wrong++ < 10)
          ADD_FAILURE() << "voxel " << i << " " << j << " " << k << " is " << value << ", written " << expected;
      }
  EXPECT_EQ(wrong, 0u) << "voxels read wrong of " << grid.size[0] * grid.size[1] * grid.size[2];
}

TEST_F(SegmentationFileTest, DicomSegBinaryPixelDataShorterThanItsFramesIsAnError)
{
  // 10 frames of 13 x 11 bits need 179 bytes (1430 bits); 9 frames 161.
  ImageGrid grid;
  grid.size = { 13, 11, 10 };
  auto message = [&](const std::string& name, std::size_t bytes, long numberOfFrames)
  {
    testing::writeDicomSegmentation(path(name), grid, { { "Slab", { 1, 0, 0 }, [](const PhysicalPoint&) { return 1.0; } } });
    testing::cutDicomFrames(path(name), bytes, numberOfFrames);
    try
    {
      readDicomSegmentation(path(name));
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return std::string(e.what());
    }
    return std::string("read without an error");
  };
  EXPECT_EQ(message("whole.dcm", 179, -1), "read without an error");
  // Number of Frames says 9 and the pixel data holds 9 frames (DCMTK checks no more; it pads the
  // 161 bytes to an even 162), but the functional groups describe 10.
  EXPECT_EQ(message("nine.dcm", 161, 9),
            path("nine.dcm") + ": the pixel data has 162 bytes; 10 frames of 11 x 13 pixels need 179");
  // A byte short of Number of Frames: DCMTK refuses it as it loads the file.
  const std::string text = message("short.dcm", 178, -1);
  EXPECT_EQ(text.rfind(path("short.dcm") + ": ", 0), 0u) << text;
  EXPECT_NE(text.find("Pixel Data"), std::string::npos) << text;
}

TEST_F(SegmentationFileTest, DicomSegFractionalCountsFromHalfTheMaximum)
{
  ImageGrid grid;
  grid.size = { 6, 4, 3 };
  // Pixel i of every row holds fraction i / 5: 0, 0.2, 0.4, 0.6, 0.8, 1 (stored as i * 51 of 255);
  // 127.5 is half, so pixels 3, 4, 5 are in (stored 153, 204, 255) and 2 (102) is not.
  testing::writeDicomSegmentation(path("fractional.dcm"), grid,
                                  { { "Ramp", { 1, 0, 0 }, [](const PhysicalPoint& p) { return p[0] / 5.0; } } }, 255);
  const SegmentationFile file = readDicomSegmentation(path("fractional.dcm"));
  ASSERT_EQ(file.layers.size(), 1u);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(valueAt(file.layers[0], grid.point(i, 2, 1)), i >= 3 ? 1.0f : 0.0f) << i;
}

TEST_F(SegmentationFileTest, DicomSegFramesOffTheGridAreErrors)
{
  const ImageGrid grid = obliqueGrid();
  const std::vector<testing::DicomSegmentSpec> segments{ { "Ball", { 1, 0, 0 }, ball(grid.point(6, 6, 4), 3.0) } };
  auto moved = [&](int slice, double along, double across)
  {
    return [=](int k)
    {
      PhysicalPoint p = grid.point(0, 0, k);
      if (k == slice)
        for (int a = 0; a < 3; ++a)
          p[a] += along * grid.axes[2][a] + across * grid.axes[0][a];
      return p;
    };
  };
  auto message = [&](const std::string& name)
  {
    try
    {
      readDicomSegmentation(path(name));
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string("read without an error");
  };
  // Half a slice up: between two slices of the grid.
  testing::writeDicomSegmentation(path("between.dcm"), grid, segments, 0, moved(5, 0.5 * grid.spacing[2], 0.0));
  EXPECT_NE(message("between.dcm").find("not a whole number of slices of 1.25 mm"), std::string::npos)
    << message("between.dcm");
  // One millimetre along the rows: off the grid in its plane.
  testing::writeDicomSegmentation(path("shifted.dcm"), grid, segments, 0, moved(3, 0.0, 1.0));
  EXPECT_NE(message("shifted.dcm").find("shifted in its plane"), std::string::npos) << message("shifted.dcm");
  // A whole slice up is a gap, not an error: the slice in between is empty.
  testing::writeDicomSegmentation(path("gap.dcm"), grid, segments, 0, moved(6, grid.spacing[2], 0.0));
  EXPECT_EQ(message("gap.dcm"), "read without an error");
}

TEST_F(SegmentationFileTest, BrokenDicomSegIsAnError)
{
  const ImageGrid grid = obliqueGrid();
  testing::writeDicomSegmentation(path("whole.dcm"), grid,
                                  { { "Ball", { 1, 0, 0 }, ball(grid.point(6, 6, 4), 3.0) } });
  fs::copy_file(path("whole.dcm"), path("truncated.dcm"));
  fs::resize_file(path("truncated.dcm"), fs::file_size(path("whole.dcm")) - 200);
  try
  {
    readSegmentationFile(path("truncated.dcm"));
    ADD_FAILURE() << "a truncated DICOM SEG was read";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("truncated.dcm"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace slicemesh

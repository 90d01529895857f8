#include "Core/SliceMeshTypes.h"
#include "DicomSeriesWriter.h"
#include "TemporaryFolderTest.h"
#include "TestVolumes.h"
#include "VolumeReader.h"

#include "itkImageFileWriter.h"

#include <gtest/gtest.h>

#include "itkMetaDataObject.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <tuple>

namespace slicemesh
{
namespace
{

namespace fs = std::filesystem;

class VolumeReaderTest : public testing::TemporaryFolderTest
{
protected:
  VolumeReaderTest()
    : TemporaryFolderTest("slicemesh-reader-")
  {
  }

  std::string writeText(const std::string& name, const std::string& text) const
  {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }

  /** A 5x4x3 volume with distinct voxel values, oblique direction and anisotropic spacing. */
  static ScalarVolume::Pointer obliqueVolume()
  {
    auto volume = testing::makeVolume({ 5, 4, 3 }, { 0.8, 0.5, 3.0 });
    ScalarVolume::PointType origin;
    origin[0] = 12.5, origin[1] = -30.25, origin[2] = 7.0;
    volume->SetOrigin(origin);
    const double c = std::cos(0.3), s = std::sin(0.3);
    ScalarVolume::DirectionType direction; // a rotation about z, then the z axis flipped
    direction.Fill(0.0);
    direction[0][0] = c, direction[0][1] = -s;
    direction[1][0] = s, direction[1][1] = c;
    direction[2][2] = -1.0;
    volume->SetDirection(direction);
    float value = 0.0f;
    for (float* voxel = volume->GetBufferPointer(); voxel != volume->GetBufferPointer() + 60; ++voxel)
      *voxel = (value += 1.0f);
    return volume;
  }

  template <typename TImage>
  static void write(const TImage* image, const std::string& file)
  {
    auto writer = itk::ImageFileWriter<TImage>::New();
    writer->SetInput(image);
    writer->SetFileName(file);
    writer->Update();
  }
};

/** Runs the call and returns the Error's message; fails the test if nothing is thrown. */
template <typename Call>
std::string errorMessageOf(Call call)
{
  try
  {
    call();
  }
  catch (const Error& error)
  {
    return error.what();
  }
  ADD_FAILURE() << "no slicemesh::Error thrown";
  return {};
}

TEST_F(VolumeReaderTest, RoundTripKeepsGeometryAndVoxels)
{
  const ScalarVolume::Pointer written = obliqueVolume();
  for (const std::string name : { "volume.nii", "volume.nii.gz", "volume.nrrd", "volume.mha" })
  {
    SCOPED_TRACE(name);
    write(written.GetPointer(), path(name));
    const ScalarVolume::Pointer read = readVolume(path(name));
    ASSERT_EQ(read->GetLargestPossibleRegion().GetSize(), written->GetLargestPossibleRegion().GetSize());
    for (unsigned int row = 0; row < 3; ++row)
    {
      // NIfTI stores geometry in single precision (and the rotation as a quaternion).
      EXPECT_NEAR(read->GetOrigin()[row], written->GetOrigin()[row], 1e-4);
      EXPECT_NEAR(read->GetSpacing()[row], written->GetSpacing()[row], 1e-6);
      for (unsigned int column = 0; column < 3; ++column)
        EXPECT_NEAR(read->GetDirection()[row][column], written->GetDirection()[row][column], 1e-5);
    }
    EXPECT_TRUE(std::equal(read->GetBufferPointer(), read->GetBufferPointer() + 60, written->GetBufferPointer()));
    // The header alone tells the same geometry (what contours drawn on the image are stacked by).
    const VolumeGeometry geometry = readVolumeGeometry(path(name));
    for (unsigned int row = 0; row < 3; ++row)
    {
      EXPECT_NEAR(geometry.spacing[row], written->GetSpacing()[row], 1e-6);
      EXPECT_NEAR(geometry.sliceDirection()[row], written->GetDirection()[row][2], 1e-5);
      for (unsigned int column = 0; column < 3; ++column)
        EXPECT_NEAR(geometry.direction[row][column], written->GetDirection()[row][column], 1e-5);
    }
  }
}

/** Expects the read volume, and the geometry of its header alone, where `written` is. */
void expectSameGeometry(const ScalarVolume* read, const VolumeGeometry& header, const ScalarVolume* written)
{
  for (unsigned int row = 0; row < 3; ++row)
  {
    EXPECT_NEAR(read->GetOrigin()[row], written->GetOrigin()[row], 1e-4) << row;
    EXPECT_NEAR(header.origin[row], written->GetOrigin()[row], 1e-4) << row;
    EXPECT_NEAR(read->GetSpacing()[row], written->GetSpacing()[row], 1e-6) << row;
    for (unsigned int column = 0; column < 3; ++column)
    {
      EXPECT_NEAR(read->GetDirection()[row][column], written->GetDirection()[row][column], 1e-5) << row << column;
      EXPECT_NEAR(header.direction[row][column], written->GetDirection()[row][column], 1e-5) << row << column;
    }
  }
}

TEST_F(VolumeReaderTest, ANrrdInLeftAnteriorSuperiorSpaceLiesWhereItsHeaderSays)
{
  // ITK 5.2 turned LAS into LPS by negating x instead of y: the volume came out mirrored left-right
  // and front-back, where 3D Slicer reads it right.
  const ScalarVolume::Pointer written = obliqueVolume();
  std::ostringstream header;
  header << "NRRD0004\ntype: float\ndimension: 3\nspace: left-anterior-superior\nsizes: 5 4 3\n"
         << "space directions:";
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const double side = written->GetSpacing()[axis];
    const auto& d = written->GetDirection();
    header << " (" << d[0][axis] * side << "," << -d[1][axis] * side << "," << d[2][axis] * side << ")";
  }
  header.precision(17);
  header << "\nspace origin: (" << written->GetOrigin()[0] << "," << -written->GetOrigin()[1] << ","
         << written->GetOrigin()[2] << ")\nendian: little\nencoding: raw\n\n";
  std::string bytes(reinterpret_cast<const char*>(written->GetBufferPointer()), 60 * sizeof(float));
  const std::string file = writeText("las.nrrd", header.str() + bytes);
  const ScalarVolume::Pointer read = readVolume(file);
  expectSameGeometry(read, readVolumeGeometry(file), written);
  EXPECT_TRUE(std::equal(read->GetBufferPointer(), read->GetBufferPointer() + 60, written->GetBufferPointer()));
}

TEST_F(VolumeReaderTest, ANiftiInMetresOrMicronsLiesWhereItsHeaderSays)
{
  // ITK 5.2 converted the spacing of such a file to millimetres but left its origin in metres or
  // microns: the volume landed near the origin, metres turned into millimetres.
  const ScalarVolume::Pointer written = obliqueVolume();
  write(written.GetPointer(), path("mm.nii"));
  std::string bytes;
  {
    std::ifstream in(path("mm.nii"), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto scaleFloat = [](std::string& header, std::size_t offset, double factor)
  {
    float value;
    std::memcpy(&value, header.data() + offset, sizeof value);
    value = static_cast<float>(value * factor);
    std::memcpy(header.data() + offset, &value, sizeof value);
  };
  for (const auto& [name, unit, factor] : { std::tuple{ "metres.nii", 1, 0.001 }, std::tuple{ "microns.nii", 3, 1000.0 } })
  {
    SCOPED_TRACE(name);
    std::string file = bytes;
    for (std::size_t offset : { 80, 84, 88 }) // pixdim[1..3]
      scaleFloat(file, offset, factor);
    for (std::size_t offset = 268; offset < 328; offset += 4) // qoffset_x, y, z, then the sform's three rows
      scaleFloat(file, offset, factor);
    file[123] = static_cast<char>((file[123] & ~0x07) | unit); // xyzt_units: the spatial unit
    std::ofstream(path(name), std::ios::binary) << file;
    const ScalarVolume::Pointer read = readVolume(path(name));
    expectSameGeometry(read, readVolumeGeometry(path(name)), written);
  }
}

TEST_F(VolumeReaderTest, AnUpperCaseMetaImageNameIsRead)
{
  // ITK's MetaImage factory knows lower-case names only: "VOLUME.MHA" was "not an image file".
  const ScalarVolume::Pointer written = obliqueVolume();
  write(written.GetPointer(), path("volume.mha"));
  fs::rename(path("volume.mha"), path("VOLUME.MHA"));
  const ScalarVolume::Pointer read = readVolume(path("VOLUME.MHA"));
  expectSameGeometry(read, readVolumeGeometry(path("VOLUME.MHA")), written);
  EXPECT_TRUE(std::equal(read->GetBufferPointer(), read->GetBufferPointer() + 60, written->GetBufferPointer()));
}

TEST_F(VolumeReaderTest, ANifti2FileIsNamedAsSuch)
{
  // ITK 5.2 reads NIfTI-1 only: a NIfTI-2 file was "not an image file SliceMesh can read".
  std::string header(540 + 4 + 64, '\0');
  const std::int32_t size = 540;
  std::memcpy(header.data(), &size, sizeof size);
  std::memcpy(header.data() + 4, "n+2\0\r\n\032\n", 8);
  const std::string message = errorMessageOf([&] { readVolume(writeText("v2.nii", header)); });
  EXPECT_NE(message.find("v2.nii: a NIfTI-2 file, which SliceMesh does not read; save it as NIfTI-1"), std::string::npos)
    << message;
}

TEST_F(VolumeReaderTest, SampleVolumeIsReadable)
{
  const ScalarVolume::Pointer sample = readVolume(SLICEMESH_DATA_DIR "/sample-labelmap.nii.gz");
  EXPECT_NEAR(sample->GetSpacing()[2], 2.0, 1e-6);
  EXPECT_NEAR(sample->GetSpacing()[0], 0.8, 1e-6);
  EXPECT_LT(sample->GetDirection()[0][0], 0.999); // oblique
}

TEST_F(VolumeReaderTest, SingleSliceVolumeIsRead)
{
  // One slice is still a 3-D volume (Logic caps it with the slice spacing), in every format.
  auto slab = testing::makeVolume({ 6, 5, 1 }, { 0.5, 0.5, 4.0 });
  for (const std::string name : { "slab.nii.gz", "slab.nrrd", "slab.mha" })
  {
    SCOPED_TRACE(name);
    write(slab.GetPointer(), path(name));
    const ScalarVolume::Pointer read = readVolume(path(name));
    EXPECT_EQ(read->GetLargestPossibleRegion().GetSize()[2], 1u);
    EXPECT_NEAR(read->GetSpacing()[2], 4.0, 1e-6);
  }
}

TEST_F(VolumeReaderTest, MissingFileIsAnError)
{
  const std::string missing = path("nothing-here.nii.gz");
  const std::string message = errorMessageOf([&] { readVolume(missing); });
  EXPECT_NE(message.find(missing), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, ADetachedHeaderWhoseDataFileIsMissingNamesThatFile)
{
  // The readers said the header itself "cannot be read".
  const std::string meta = path("detached.mhd"), nrrd = path("detached.nhdr");
  std::ofstream(meta) << "ObjectType = Image\nNDims = 3\nBinaryData = True\nElementSpacing = 1 1 1\nDimSize = 4 4 4\n"
                         "ElementType = MET_UCHAR\nElementDataFile = nothere.raw\n";
  std::ofstream(nrrd) << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nspacings: 1 1 1\nencoding: raw\n"
                         "data file: elsewhere.raw\n";
  for (const auto& [file, data] : { std::pair{ meta, std::string("nothere.raw") }, std::pair{ nrrd, std::string("elsewhere.raw") } })
  {
    const std::string message = errorMessageOf([&] { readStoredVolume(file); });
    EXPECT_NE(message.find(file + ": its voxels are in '" + data + "', which does not exist"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Present, it is read.
  std::ofstream(path("nothere.raw"), std::ios::binary) << std::string(64, '\1');
  EXPECT_EQ(readVolume(meta)->GetLargestPossibleRegion().GetNumberOfPixels(), 64u);
}

TEST_F(VolumeReaderTest, TextFileNamedNiftiIsAnError)
{
  const std::string file = writeText("notes.nii", "this is not an image\njust some text\n");
  const std::string message = errorMessageOf([&] { readVolume(file); });
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, TruncatedGzipIsAnError)
{
  auto big = testing::makeVolume({ 64, 64, 32 });
  std::mt19937 random(3);
  for (float* voxel = big->GetBufferPointer(); voxel != big->GetBufferPointer() + 64 * 64 * 32; ++voxel)
    *voxel = static_cast<float>(random() % 1000); // noise compresses badly: a long stream
  write(big.GetPointer(), path("whole.nii.gz"));
  const auto wholeSize = fs::file_size(path("whole.nii.gz"));
  fs::copy_file(path("whole.nii.gz"), path("cut.nii.gz"));
  fs::resize_file(path("cut.nii.gz"), wholeSize / 2);
  const std::string message = errorMessageOf([&] { readVolume(path("cut.nii.gz")); });
  EXPECT_NE(message.find("cut.nii.gz"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, ScaledNiftiIsReadScaledAndItsStoredSizeChecked)
{
  // An uncompressed NIfTI of 2-byte voxels with scl_slope 2 and scl_inter 10 (as scanners write MR):
  // ITK reports it as float, but the file holds 2 bytes a voxel. It is read, scaled; cut short, it
  // is refused as truncated by what it stores.
  using ShortVolume = itk::Image<short, 3>;
  auto stored = ShortVolume::New();
  stored->SetRegions(ShortVolume::SizeType{ { 6, 5, 4 } });
  stored->Allocate();
  short value = 0;
  for (short* voxel = stored->GetBufferPointer(); voxel != stored->GetBufferPointer() + 120; ++voxel)
    *voxel = value++;
  write(stored.GetPointer(), path("scaled.nii"));
  {
    std::fstream file(path("scaled.nii"), std::ios::in | std::ios::out | std::ios::binary);
    const float slope = 2.0f, intercept = 10.0f; // little-endian, as ITK wrote the header on this machine
    file.seekp(112);
    file.write(reinterpret_cast<const char*>(&slope), 4);
    file.write(reinterpret_cast<const char*>(&intercept), 4);
  }
  const ScalarVolume::Pointer read = readVolume(path("scaled.nii"));
  ASSERT_EQ(read->GetLargestPossibleRegion().GetNumberOfPixels(), 120u);
  for (std::size_t i = 0; i < 120; ++i)
    EXPECT_EQ(read->GetBufferPointer()[i], 2.0f * static_cast<float>(i) + 10.0f) << i;

  fs::copy_file(path("scaled.nii"), path("cut.nii"));
  fs::resize_file(path("cut.nii"), 352 + 2 * 100);
  const std::string message = errorMessageOf([&] { readVolume(path("cut.nii")); });
  EXPECT_NE(message.find("cut.nii: a truncated NIfTI file (552 bytes; its header promises at least 592)"),
            std::string::npos)
    << message;
}

TEST_F(VolumeReaderTest, TwoDimensionalImageIsAnError)
{
  using Image2D = itk::Image<float, 2>;
  auto image = Image2D::New();
  image->SetRegions(Image2D::SizeType{ { 8, 8 } });
  image->Allocate(true);
  write(image.GetPointer(), path("input.nii"));
  const std::string message = errorMessageOf([&] { readVolume(path("input.nii")); });
  EXPECT_NE(message.find("input.nii: a 2-D image; SliceMesh needs a 3-D volume"), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, FourDimensionalImageIsAnErrorUnlessOneTimePoint)
{
  using Image4D = itk::Image<float, 4>;
  auto series = Image4D::New();
  series->SetRegions(Image4D::SizeType{ { 4, 4, 4, 3 } });
  series->Allocate(true);
  write(series.GetPointer(), path("series.nii"));
  const std::string message = errorMessageOf([&] { readVolume(path("series.nii")); });
  EXPECT_NE(message.find("a 4-D image"), std::string::npos) << message;

  auto single = Image4D::New();
  single->SetRegions(Image4D::SizeType{ { 4, 5, 6, 1 } });
  Image4D::SpacingType spacing;
  spacing[0] = 0.5, spacing[1] = 0.75, spacing[2] = 2.0, spacing[3] = 1.0;
  single->SetSpacing(spacing);
  Image4D::DirectionType direction;
  direction.SetIdentity();
  direction[0][0] = -1.0, direction[1][1] = -1.0; // LPS <-> RAS: a common 4-D NIfTI geometry
  single->SetDirection(direction);
  single->Allocate(true);
  write(single.GetPointer(), path("single.nii"));
  const ScalarVolume::Pointer volume = readVolume(path("single.nii"));
  EXPECT_EQ(volume->GetLargestPossibleRegion().GetSize()[2], 6u);
  EXPECT_NEAR(volume->GetSpacing()[1], 0.75, 1e-6);
  EXPECT_NEAR(volume->GetDirection()[0][0], -1.0, 1e-6);
}

std::string metaImageHeader(const std::string& spacing, const std::string& transform)
{
  return "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementSpacing = " + spacing +
         "\nTransformMatrix = " + transform + "\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" +
         std::string(8, '\1');
}

TEST_F(VolumeReaderTest, BadSpacingIsAnError)
{
  const std::string identity = "1 0 0 0 1 0 0 0 1";
  for (const std::string spacing : { "0 1 1", "1 -2 1", "1 1 nan" })
  {
    SCOPED_TRACE(spacing);
    const std::string file = writeText("spacing.mha", metaImageHeader(spacing, identity));
    const std::string message = errorMessageOf([&] { readVolume(file); });
    EXPECT_NE(message.find("spacing"), std::string::npos) << message;
  }
}

TEST_F(VolumeReaderTest, SingularDirectionIsAnError)
{
  const std::string file = writeText("flat.mha", metaImageHeader("1 1 1", "1 0 0 1 0 0 0 0 1"));
  const std::string message = errorMessageOf([&] { readVolume(file); });
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, DicomSeriesDirectoryRoundTrip)
{
  // A CT series written slice by slice, each slice carrying its position and the orientation.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 6, 5, 4 }, { 0.7, 0.7, 2.5 });
  ShortVolume::PointType origin;
  origin[0] = -20.0, origin[1] = 15.5, origin[2] = 100.0;
  volume->SetOrigin(origin);
  const double c = std::cos(0.2), s = std::sin(0.2);
  ShortVolume::DirectionType direction; // a tilt about the x axis
  direction.SetIdentity();
  direction[1][1] = c, direction[1][2] = -s;
  direction[2][1] = s, direction[2][2] = c;
  volume->SetDirection(direction);
  for (long n = 0; n < 120; ++n)
    volume->GetBufferPointer()[n] = static_cast<short>(n * 3);

  const fs::path dicom = folder() / "series";
  testing::writeCTSeries(volume, dicom);

  const ScalarVolume::Pointer read = readVolume(dicom.string());
  ASSERT_EQ(read->GetLargestPossibleRegion().GetSize()[2], 4u);
  for (unsigned int row = 0; row < 3; ++row)
  {
    EXPECT_NEAR(read->GetOrigin()[row], origin[row], 1e-3);
    EXPECT_NEAR(read->GetSpacing()[row], volume->GetSpacing()[row], 1e-3);
    for (unsigned int column = 0; column < 3; ++column)
      EXPECT_NEAR(read->GetDirection()[row][column], direction[row][column], 1e-4);
  }
  for (long n = 0; n < 120; ++n)
    ASSERT_EQ(read->GetBufferPointer()[n], n * 3.0f) << "voxel " << n;
  // Without the voxels: the slice direction and the spacing between the slices' positions.
  const VolumeGeometry geometry = readVolumeGeometry(dicom.string());
  for (unsigned int row = 0; row < 3; ++row)
  {
    EXPECT_NEAR(geometry.spacing[row], volume->GetSpacing()[row], 1e-3);
    EXPECT_NEAR(geometry.sliceDirection()[row], direction[row][2], 1e-4);
  }
  EXPECT_NE(errorMessageOf([&] { readVolumeGeometry(path("none.nrrd")); }).find("no such file"), std::string::npos);
}

TEST_F(VolumeReaderTest, DicomSeriesWithAMissingSliceIsAnError)
{
  // The series reader spaces the slices evenly between the first and the last: with one missing,
  // every slice after the gap would be put half a spacing or more from where it was scanned.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 4, 4, 6 }, { 0.8, 0.8, 2.5 });
  const fs::path dicom = folder() / "series";
  testing::writeCTSeries(volume, dicom);
  ASSERT_TRUE(fs::remove(dicom / "slice005.dcm")); // the last: still evenly spaced, one slice fewer
  EXPECT_EQ(readVolume(dicom.string())->GetLargestPossibleRegion().GetSize()[2], 5u);

  ASSERT_TRUE(fs::remove(dicom / "slice002.dcm"));
  for (const std::string& message : { errorMessageOf([&] { readVolume(dicom.string()); }),
                                      errorMessageOf([&] { readVolumeGeometry(dicom.string()); }) })
  {
    EXPECT_NE(message.find("not evenly spaced"), std::string::npos) << message;
    EXPECT_NE(message.find("slice001.dcm and slice003.dcm are 5 mm apart where the others are 2.5 mm"), std::string::npos)
      << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(VolumeReaderTest, GantryTiltedDicomSeriesKeepsEachSliceWhereItWasScanned)
{
  // A head CT scanned with the gantry tilted 15 degrees: axial slices, each shifted 0.67 mm
  // posteriorly from the one before. The series reader stacked them straight along their normal,
  // 2.59 mm apart instead of 2.5 (the mesh 3.5% too tall and up to the whole shift out of place).
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 6, 5, 8 });
  const double tilt = 15.0 * 3.14159265358979323846 / 180.0, spacingBetweenPlanes = 2.5;
  ShortVolume::SpacingType spacing;
  spacing[0] = 0.7, spacing[1] = 0.6, spacing[2] = spacingBetweenPlanes / std::cos(tilt);
  volume->SetSpacing(spacing);
  ShortVolume::PointType origin;
  origin[0] = -20.0, origin[1] = 15.5, origin[2] = -300.0;
  volume->SetOrigin(origin);
  ShortVolume::DirectionType sheared; // axial rows and columns; the third axis leans towards +y
  sheared.SetIdentity();
  sheared[1][2] = std::sin(tilt), sheared[2][2] = std::cos(tilt);
  volume->SetDirection(sheared);
  for (long n = 0; n < 240; ++n)
    volume->GetBufferPointer()[n] = static_cast<short>(n);
  const fs::path dicom = folder() / "tilted";
  testing::writeCTSeries(volume, dicom);

  const ScalarVolume::Pointer read = readVolume(dicom.string());
  ASSERT_EQ(read->GetLargestPossibleRegion().GetSize()[2], 8u);
  for (const ScalarVolume::IndexType index : { ScalarVolume::IndexType{ { 0, 0, 0 } }, ScalarVolume::IndexType{ { 5, 4, 7 } },
                                               ScalarVolume::IndexType{ { 2, 1, 4 } } })
  {
    ScalarVolume::PointType expected, found;
    volume->TransformIndexToPhysicalPoint(index, expected);
    read->TransformIndexToPhysicalPoint(index, found);
    for (unsigned int row = 0; row < 3; ++row)
      EXPECT_NEAR(found[row], expected[row], 1e-3) << "voxel " << index << ", axis " << row;
    EXPECT_EQ(read->GetPixel(index), volume->GetPixel(index));
  }
  // Contours drawn on it lie in its axial planes, 2.5 mm apart.
  const VolumeGeometry geometry = readVolumeGeometry(dicom.string());
  EXPECT_NEAR(geometry.sliceNormal()[0], 0.0, 1e-6);
  EXPECT_NEAR(geometry.sliceNormal()[1], 0.0, 1e-6);
  EXPECT_NEAR(geometry.sliceNormal()[2], 1.0, 1e-6);
  EXPECT_NEAR(geometry.sliceDistance(), spacingBetweenPlanes, 1e-4);
}

TEST_F(VolumeReaderTest, AFolderOfTwoSeriesSaysWhichWasRead)
{
  // Two reconstructions of one scan exported together, of as many slices: one is read, and the
  // volume's metadata says which (the command line prints it); one series alone says nothing.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 4, 4, 5 }, { 0.8, 0.8, 2.5 });
  const fs::path dicom = folder() / "series", other = folder() / "other";
  testing::writeCTSeries(volume, dicom);
  std::string choice;
  EXPECT_FALSE(itk::ExposeMetaData<std::string>(readVolume(dicom.string())->GetMetaDataDictionary(), seriesChoiceKey, choice));
  testing::writeCTSeries(volume, other);
  for (int k = 0; k < 5; ++k)
    fs::rename(other / ("slice00" + std::to_string(k) + ".dcm"), dicom / ("other00" + std::to_string(k) + ".dcm"));
  const ScalarVolume::Pointer read = readVolume(dicom.string());
  EXPECT_EQ(read->GetLargestPossibleRegion().GetSize()[2], 5u);
  ASSERT_TRUE(itk::ExposeMetaData<std::string>(read->GetMetaDataDictionary(), seriesChoiceKey, choice));
  EXPECT_NE(choice.find("holds 2 image series (5 files from "), std::string::npos) << choice;
  EXPECT_NE(choice.find(", the first of the largest; give a folder of one series to choose another"), std::string::npos)
    << choice;
  EXPECT_EQ(choice.find('\n'), std::string::npos) << choice;
}

TEST_F(VolumeReaderTest, DicomSeriesOfSlicesInTwoOrientationsIsAnError)
{
  // One series whose last three slices are turned 5 degrees about the normal (as the planes of a
  // three-plane localizer share one series): the reader would place them in the first's orientation.
  using ShortVolume = itk::Image<short, 3>;
  auto lower = testing::makeImage<ShortVolume>({ 4, 4, 3 }, { 0.8, 0.8, 2.5 });
  auto upper = testing::makeImage<ShortVolume>({ 4, 4, 3 }, { 0.8, 0.8, 2.5 });
  ShortVolume::PointType origin;
  origin.Fill(0.0);
  origin[2] = 7.5;
  upper->SetOrigin(origin);
  const double turn = 5.0 * 3.14159265358979323846 / 180.0;
  ShortVolume::DirectionType turned;
  turned.SetIdentity();
  turned[0][0] = std::cos(turn), turned[0][1] = -std::sin(turn);
  turned[1][0] = std::sin(turn), turned[1][1] = std::cos(turn);
  upper->SetDirection(turned);
  const fs::path dicom = folder() / "series", other = folder() / "upper";
  const std::string series = "1.2.826.0.1.3680043.2.1125.1.7";
  testing::writeCTSeries(lower, dicom, series);
  testing::writeCTSeries(upper, other, series); // moved in as slices 3 to 5
  for (int k = 0; k < 3; ++k)
    fs::rename(other / ("slice00" + std::to_string(k) + ".dcm"), dicom / ("slice00" + std::to_string(k + 3) + ".dcm"));
  const std::string message = errorMessageOf([&] { readVolume(dicom.string()); });
  EXPECT_NE(message.find("not all of one orientation: slice003.dcm is turned 5 degrees from slice000.dcm"), std::string::npos)
    << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, DicomSeriesOfTwoEchoesIsRefusedAsImagesSharingPositions)
{
  // Two echoes of one MR, one series: each position holds two images. Refused (right) as a slice
  // missing; the message now says what the files are.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 4, 4, 4 }, { 0.8, 0.8, 2.5 });
  const fs::path dicom = folder() / "series", other = folder() / "echo2";
  const std::string series = "1.2.826.0.1.3680043.2.1125.1.8";
  testing::writeCTSeries(volume, dicom, series);
  testing::writeCTSeries(volume, other, series);
  for (int k = 0; k < 4; ++k)
    fs::rename(other / ("slice00" + std::to_string(k) + ".dcm"), dicom / ("echo00" + std::to_string(k) + ".dcm"));
  const std::string message = errorMessageOf([&] { readVolume(dicom.string()); });
  EXPECT_NE(message.find("are at one position (echoes, phases or repeats of one scan?)"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, DicomSeriesWhoseOrientationIsNotTwoUnitVectorsIsAnError)
{
  // A column direction of length 0.8 was read as it is: a grid stretched by a quarter, exit 0.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 4, 4, 4 }, { 0.8, 0.8, 2.5 });
  const fs::path dicom = folder() / "series";
  testing::writeCTSeries(volume, dicom);
  for (int k = 0; k < 4; ++k)
    testing::rewriteDicomString(dicom / ("slice00" + std::to_string(k) + ".dcm"), 0x0020, 0x0037, "1\\0\\0\\0\\0.8\\0");
  const std::string message = errorMessageOf([&] { readVolume(dicom.string()); });
  EXPECT_NE(message.find("is not two perpendicular unit vectors (lengths 1 and 0.8"), std::string::npos) << message;
}

TEST_F(VolumeReaderTest, OneDicomSliceIsAnErrorButOneMultiFrameFileIsAVolume)
{
  // GDCM gives a single-frame file as a slice 1 mm thick, a thickness it makes up: a slice of a
  // series given instead of its folder was meshed as a 1 mm slab.
  using ShortVolume = itk::Image<short, 3>;
  auto volume = testing::makeImage<ShortVolume>({ 4, 4, 5 }, { 0.8, 0.8, 2.5 });
  const fs::path dicom = folder() / "series";
  testing::writeCTSeries(volume, dicom);
  const std::string message = errorMessageOf([&] { readVolume((dicom / "slice002.dcm").string()); });
  EXPECT_NE(message.find("slice002.dcm: a single DICOM slice (a 2-D image)"), std::string::npos) << message;
  EXPECT_NE(message.find("give the folder of its series"), std::string::npos) << message;

  // A folder holding one file of five frames (an enhanced CT) is that volume, not "a single slice".
  const fs::path multiFrame = folder() / "enhanced";
  fs::create_directories(multiFrame);
  testing::writeMultiFrameFile(volume, multiFrame / "volume.dcm");
  EXPECT_EQ(readVolume(multiFrame.string())->GetLargestPossibleRegion().GetSize()[2], 5u);
}

TEST_F(VolumeReaderTest, DirectoryWithoutDicomIsAnError)
{
  writeText("readme.txt", "no images here\n");
  const std::string message = errorMessageOf([&] { readVolume(folder().string()); });
  EXPECT_NE(message.find("DICOM"), std::string::npos) << message;
}

} // namespace
} // namespace slicemesh

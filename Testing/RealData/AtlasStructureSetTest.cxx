// A real-anatomy structure set: ten AAL atlas structures contoured by plastimatch into an RTSTRUCT
// (Testing/Data/README.md says how), meshed by the executable and each ROI's volume compared with
// its label's voxel volume in the atlas.
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "MeshReader.h"
#include "Measures/MeshValidation.h"
#include "VolumeReader.h"

#include <gtest/gtest.h>

#include <itkImageRegionConstIterator.h>

#include <iostream>
#include <map>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

// |mesh volume / voxel volume - 1|; measured 0.13% to 0.53%: the finished surface encloses the
// contours' prism volume (each slice's area times its thickness, ending half a slice beyond the end
// contours, as the voxels do), and plastimatch's contours enclose a little less than the voxels.
constexpr double volumeTolerance = 0.01;

TEST(AtlasStructureSet, TenAALStructuresFromPlastimatchMatchTheirVoxelVolumes)
{
  const std::map<std::string, int> labels{ { "Hippocampus_L", 37 }, { "Hippocampus_R", 38 }, { "Amygdala_L", 41 },
                                           { "Amygdala_R", 42 },    { "Caudate_L", 71 },     { "Caudate_R", 72 },
                                           { "Putamen_L", 73 },     { "Putamen_R", 74 },     { "Thalamus_L", 77 },
                                           { "Thalamus_R", 78 } };
  const ScalarVolume::Pointer atlas = readVolume("/usr/share/mricron/templates/aal.nii.gz");
  const auto spacing = atlas->GetSpacing();
  std::map<int, double> voxelVolume;
  for (itk::ImageRegionConstIterator<ScalarVolume> it(atlas, atlas->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
    voxelVolume[static_cast<int>(it.Get())] += spacing[0] * spacing[1] * spacing[2];

  const fs::path folder = freshFolder("AtlasStructureSet");
  const RunResult r = runSliceMesh("--outputDirectory " + quoted((folder / "rois").string()) + " " +
                                   quoted(SLICEMESH_TEST_DATA_DIR "/aal-10-structures-rtstruct.dcm") + " " +
                                   quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  std::size_t meshes = 0;
  for (const auto& entry : fs::directory_iterator(folder / "rois"))
  {
    const std::string file = entry.path().filename().string();
    const std::string name = file.substr(file.find('_') + 1, file.size() - file.find('_') - 5);
    ASSERT_EQ(labels.count(name), 1u) << file;
    const MeshValidation v = validateMesh(readMesh(entry.path().string()).mesh);
    EXPECT_TRUE(v.valid()) << file << ": " << v.summary();
    const double expected = voxelVolume[labels.at(name)];
    std::cout << name << ": mesh " << v.volume << " mm^3, voxels " << expected << " mm^3, ratio " << v.volume / expected
              << std::endl;
    EXPECT_NEAR(v.volume / expected, 1.0, volumeTolerance) << file << ": " << v.volume << " mm^3 against "
                                                           << expected << " mm^3 of voxels";
    ++meshes;
  }
  EXPECT_EQ(meshes, labels.size());
}

} // namespace
} // namespace slicemesh::testing

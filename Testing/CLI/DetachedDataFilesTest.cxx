// detachedDataFiles: the files a volume header names as its data, in each form the readers take;
// only headers are written here (their data files need not exist to be named).
#include "DetachedDataFiles.h"

#include "CLITestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

using cli::detachedDataFiles;
using Names = std::vector<std::string>;

fs::path writeText(const fs::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

const std::string nrrdFields = "NRRD0005\ntype: unsigned char\ndimension: 3\nsizes: 4 4 3\nencoding: raw\n";
const std::string metaFields = "ObjectType = Image\nNDims = 3\nDimSize = 4 4 3\nElementType = MET_UCHAR\n";

TEST(DetachedDataFiles, ANrrdsDataFileInEachOfItsForms)
{
  const fs::path folder = freshFolder("detached-nrrd");
  const std::string at = folder.string() + "/";
  EXPECT_EQ(detachedDataFiles(writeText(folder / "one.nhdr", nrrdFields + "data file: voxels.raw\n").string()),
            Names{ at + "voxels.raw" });
  EXPECT_EQ(detachedDataFiles(writeText(folder / "short.nhdr", nrrdFields + "datafile: /data/v.raw.gz\n").string()),
            Names{ "/data/v.raw.gz" });
  EXPECT_EQ(detachedDataFiles(writeText(folder / "list.nhdr", nrrdFields + "data file: LIST 2\na.raw\nsub/b.raw\n\nc.raw\n").string()),
            (Names{ at + "a.raw", at + "sub/b.raw", at + "c.raw" }));
  EXPECT_EQ(detachedDataFiles(writeText(folder / "format.nhdr", nrrdFields + "data file: s%03d.raw 8 12 2 2\n").string()),
            (Names{ at + "s008.raw", at + "s010.raw", at + "s012.raw" }));
  EXPECT_EQ(detachedDataFiles(writeText(folder / "down.nhdr", nrrdFields + "data file: %2d%%.raw 2 0 -1\n").string()),
            (Names{ at + " 2%.raw", at + " 1%.raw", at + " 0%.raw" }));
  // A key/value pair and a comment are no field; the data after the empty line ending the header is not read.
  EXPECT_EQ(detachedDataFiles(writeText(folder / "attached.nrrd", nrrdFields + "#data file: x.raw\ndata file:=x.raw\n\n"
                                                                                 "data file: voxels.raw\n")
                                .string()),
            Names{});
  // A format that is not one integer conversion names nothing, as no reader reads it.
  EXPECT_EQ(detachedDataFiles(writeText(folder / "bad.nhdr", nrrdFields + "data file: %s%d.raw 1 2 1\n").string()), Names{});
}

TEST(DetachedDataFiles, AMetaImagesElementDataFileButLocal)
{
  const fs::path folder = freshFolder("detached-meta");
  const std::string at = folder.string() + "/";
  EXPECT_EQ(detachedDataFiles(writeText(folder / "one.mhd", metaFields + "ElementDataFile = my voxels.raw\n").string()),
            Names{ at + "my voxels.raw" });
  EXPECT_EQ(detachedDataFiles(writeText(folder / "list.mhd", metaFields + "ElementDataFile = LIST\na.raw\nb.raw\n").string()),
            (Names{ at + "a.raw", at + "b.raw" }));
  EXPECT_EQ(detachedDataFiles(writeText(folder / "format.mhd", metaFields + "ElementDataFile = i%02d.raw 1 3 1\n").string()),
            (Names{ at + "i01.raw", at + "i02.raw", at + "i03.raw" }));
  EXPECT_EQ(detachedDataFiles(writeText(folder / "local.mha", metaFields + "ElementDataFile = LOCAL\n\x01\x02").string()),
            Names{});
}

TEST(DetachedDataFiles, TheOtherHalfOfAnAnalyzePairAndNothingForOtherFiles)
{
  const fs::path folder = freshFolder("detached-pair");
  EXPECT_EQ(detachedDataFiles(writeText(folder / "brain.hdr", std::string(348, '\0')).string()),
            Names{ (folder / "brain.img").string() });
  EXPECT_EQ(detachedDataFiles(writeText(folder / "brain.IMG", std::string(64, '\0')).string()),
            Names{ (folder / "brain.hdr").string() });
  EXPECT_EQ(detachedDataFiles(writeText(folder / "volume.nii", std::string(352, '\0')).string()), Names{});
  EXPECT_EQ(detachedDataFiles((folder / "missing.nhdr").string()), Names{});
  EXPECT_EQ(detachedDataFiles(folder.string()), Names{}) << "a DICOM folder";
}

} // namespace
} // namespace slicemesh::testing

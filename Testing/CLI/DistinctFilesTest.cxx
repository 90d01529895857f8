// A run whose output is named as one of its inputs or as another of its outputs: refused before any
// work (exit 2, one line naming both options and the path), the file that would have been
// overwritten left byte for byte as it was. Each input here is one SliceMesh meshes, so that a run
// not refused would overwrite it.
#include "CLITestSupport.h"
#include "ExitCodes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

/** A ball of label 1, 6 voxels in radius, in a 20^3 label map of 1 mm voxels. */
fs::path writeBall(const fs::path& path)
{
  writeMetaImage(path, { 20, 20, 20 }, { 1.0, 1.0, 1.0 },
                 [](int i, int j, int k)
                 { return (i - 9.5) * (i - 9.5) + (j - 9.5) * (j - 9.5) + (k - 9.5) * (k - 9.5) < 36.0 ? 1 : 0; });
  return path;
}

/** 3D Slicer's planar contours of a cylinder (VTK XML polydata, ASCII): four closed circles of
 *  radius 10 mm, 2 mm apart, and the ROI's name in a LabelName field. */
fs::path writeContourFile(const fs::path& path, const std::string& name)
{
  std::ostringstream points, connectivity, offsets;
  const int perCircle = 24;
  for (int k = 0; k < 4; ++k)
  {
    for (int a = 0; a < perCircle; ++a)
    {
      const double angle = 2.0 * M_PI * a / perCircle;
      points << 10.0 * std::cos(angle) << " " << 10.0 * std::sin(angle) << " " << 2.0 * k << " ";
      connectivity << k * perCircle + a << " ";
    }
    connectivity << k * perCircle << " "; // closed: back to the first point
    offsets << (k + 1) * (perCircle + 1) << " ";
  }
  std::ostringstream nameCodes; // VTK's ASCII string array: character codes, each string ended by 0
  for (const char c : name)
    nameCodes << static_cast<int>(static_cast<unsigned char>(c)) << " ";
  nameCodes << 0;
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n"
                      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
                      << "<FieldData><Array type=\"String\" Name=\"LabelName\" NumberOfTuples=\"1\" format=\"ascii\">"
                      << nameCodes.str() << "</Array></FieldData>\n"
                      << "<Piece NumberOfPoints=\"" << 4 * perCircle
                      << "\" NumberOfVerts=\"0\" NumberOfLines=\"4\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                      << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
                      << points.str() << "</DataArray></Points>\n"
                      << "<Lines><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" << connectivity.str()
                      << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << offsets.str()
                      << "</DataArray></Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return path;
}

/** The ball's voxels, raw: the data file a detached header names. */
std::string ballVoxels()
{
  std::string voxels;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
        voxels += (i - 9.5) * (i - 9.5) + (j - 9.5) * (j - 9.5) + (k - 9.5) * (k - 9.5) < 36.0 ? '\1' : '\0';
  return voxels;
}

/** Byte for byte as it was (compared without printing a mesh's bytes when it is not). */
void expectUnchanged(const fs::path& file, const std::string& before)
{
  const std::string now = fileText(file);
  EXPECT_TRUE(now == before) << file << " was overwritten: " << now.size() << " bytes, " << before.size() << " before";
}

/** Exit 2 and one line on stderr naming both options and the path. */
void expectRefused(const RunResult& r, const std::string& first, const std::string& second, const std::string& path)
{
  EXPECT_EQ(r.exitCode, cli::BadArguments) << r.err;
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find(first + " and " + second + " are the same file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
}

TEST(DistinctFiles, ReturnParameterFileNamedAsTheInputVolumeIsRefused)
{
  const fs::path folder = freshFolder("distinct-return-input");
  const fs::path input = writeBall(folder / "in.mha");
  const std::string before = fileText(input);
  const fs::path output = folder / "out.vtp";
  expectRefused(runSliceMesh("--returnparameterfile " + quoted(input.string()) + " " + quoted(input.string()) + " " +
                             quoted(output.string())),
                "<inputVolume>", "--returnparameterfile", input.string());
  // Spelled another way, from the folder itself: the same file as the file system sees it.
  expectRefused(runCommand("cd " + quoted(folder.string()) + " && " + quoted(SLICEMESH_EXECUTABLE) +
                           " --returnparameterfile ./in.mha in.mha out.vtp"),
                "<inputVolume>", "--returnparameterfile", "in.mha");
  expectUnchanged(input, before);
  EXPECT_FALSE(fs::exists(output)) << "refused before any work";
}

TEST(DistinctFiles, ReturnParameterFileNamedAsTheOutputModelIsRefused)
{
  const fs::path folder = freshFolder("distinct-return-output");
  const fs::path input = writeBall(folder / "in.mha");
  const fs::path output = folder / "out.vtp";
  std::ofstream(output) << "an earlier run's mesh";
  expectRefused(runSliceMesh("--returnparameterfile " + quoted(output.string()) + " " + quoted(input.string()) + " " +
                             quoted(output.string())),
                "<outputModel>", "--returnparameterfile", output.string());
  expectUnchanged(output, "an earlier run's mesh");
}

TEST(DistinctFiles, ReportNamedAsTheReturnParameterFileIsRefused)
{
  const fs::path folder = freshFolder("distinct-report-return");
  const fs::path input = writeBall(folder / "in.mha");
  const fs::path report = folder / "r.json";
  std::ofstream(report) << "{ \"an earlier\": \"report\" }";
  const fs::path output = folder / "out.vtp";
  expectRefused(runSliceMesh("--report " + quoted(report.string()) + " --returnparameterfile " +
                             quoted(report.string()) + " " + quoted(input.string()) + " " + quoted(output.string())),
                "--report", "--returnparameterfile", report.string());
  expectUnchanged(report, "{ \"an earlier\": \"report\" }");
  EXPECT_FALSE(fs::exists(output));
}

TEST(DistinctFiles, ContourFileNamedAsTheOutputModelIsRefused)
{
  const fs::path folder = freshFolder("distinct-contours-output");
  const fs::path contours = writeContourFile(folder / "c1.vtp", "Body");
  const std::string before = fileText(contours);
  // The contour file as the input itself, and as --inputContours beside the image it was drawn on.
  expectRefused(runSliceMesh(quoted(contours.string()) + " " + quoted(contours.string())), "<inputVolume>",
                "<outputModel>", contours.string());
  const fs::path image = writeBall(folder / "in.mha");
  expectRefused(runSliceMesh("--inputContours " + quoted(contours.string()) + " " + quoted(image.string()) + " " +
                             quoted(contours.string())),
                "--inputContours", "<outputModel>", contours.string());
  // An output that is a link to the input: the mesh would be written through it.
  fs::create_symlink("c1.vtp", folder / "link.vtp");
  expectRefused(runSliceMesh(quoted(contours.string()) + " " + quoted((folder / "link.vtp").string())),
                "<inputVolume>", "<outputModel>", contours.string());
  expectUnchanged(contours, before);
}

TEST(DistinctFiles, AnROIsMeshNamedAsTheInputInTheOutputFolderIsRefused)
{
  // ROI 1 "Body" of a contour file is written as 001_Body.vtp into --outputDirectory: where the
  // contour file itself lies under that name, its mesh would replace it.
  const fs::path folder = freshFolder("distinct-structure-file");
  const fs::path contours = writeContourFile(folder / "c1.vtp", "Body");
  const fs::path rois = folder / "rois";
  const RunResult written =
    runSliceMesh("--outputDirectory " + quoted(rois.string()) + " " + quoted(contours.string()) + " " +
                 quoted((folder / "all.vtp").string()));
  ASSERT_EQ(written.exitCode, cli::Success) << written.err;
  ASSERT_TRUE(fs::exists(rois / "001_Body.vtp")) << "the name a refused run's ROI mesh would have";

  const fs::path input = rois / "001_Body.vtp";
  fs::copy_file(contours, input, fs::copy_options::overwrite_existing);
  const RunResult r = runSliceMesh("--outputDirectory " + quoted(rois.string()) + " " + quoted(input.string()) + " " +
                                   quoted((folder / "again.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::BadArguments) << r.err;
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("ROI 1 (Body): its mesh in --outputDirectory and <inputVolume> are the same file '" +
                       input.string() + "'"),
            std::string::npos)
    << r.err;
  expectUnchanged(input, fileText(contours));
  EXPECT_FALSE(fs::exists(folder / "again.vtp"));
}

TEST(DistinctFiles, AnOutputNamedAsTheDataFileOfADetachedHeaderIsRefused)
{
  // A header's voxels are in a file of any name, even one of a mesh's extension: writing the mesh
  // there would overwrite the input's voxels.
  const fs::path folder = freshFolder("distinct-detached-data");
  const std::string voxels = ballVoxels();
  const fs::path nrrdData = folder / "payload.stl";
  std::ofstream(nrrdData, std::ios::binary) << voxels;
  const fs::path nrrd = folder / "ball.nhdr";
  std::ofstream(nrrd) << "NRRD0004\ntype: unsigned char\ndimension: 3\nsizes: 20 20 20\n"
                      << "spacings: 1 1 1\nencoding: raw\ndata file: payload.stl\n";
  expectRefused(runSliceMesh(quoted(nrrd.string()) + " " + quoted(nrrdData.string())),
                "the data file of <inputVolume>", "<outputModel>", nrrdData.string());
  expectUnchanged(nrrdData, voxels);

  const fs::path metaData = folder / "voxels.json";
  std::ofstream(metaData, std::ios::binary) << voxels;
  const fs::path meta = folder / "ball.mhd";
  std::ofstream(meta) << "ObjectType = Image\nNDims = 3\nDimSize = 20 20 20\nElementSpacing = 1 1 1\n"
                      << "ElementType = MET_UCHAR\nElementDataFile = voxels.json\n";
  expectRefused(runSliceMesh("--report " + quoted(metaData.string()) + " " + quoted(meta.string()) + " " +
                             quoted((folder / "out.vtp").string())),
                "the data file of <inputVolume>", "--report", metaData.string());
  expectUnchanged(metaData, voxels);
  EXPECT_FALSE(fs::exists(folder / "out.vtp"));

  // The headers are good ones: meshed into a file of its own, each run succeeds.
  EXPECT_EQ(runSliceMesh(quoted(nrrd.string()) + " " + quoted((folder / "n.vtp").string())).exitCode, cli::Success);
  EXPECT_EQ(runSliceMesh(quoted(meta.string()) + " " + quoted((folder / "m.vtp").string())).exitCode, cli::Success);
}

TEST(DistinctFiles, FilesOfTheirOwnAndOneInputGivenTwiceAreAccepted)
{
  const fs::path folder = freshFolder("distinct-accepted");
  const fs::path input = writeBall(folder / "in.mha");
  const RunResult r = runSliceMesh("--report " + quoted((folder / "r.json").string()) + " --returnparameterfile " +
                                   quoted((folder / "r.params").string()) + " " + quoted(input.string()) + " " +
                                   quoted((folder / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
  // The contour file as --inputContours and as the input (no image beside it): read twice, written never.
  const fs::path contours = writeContourFile(folder / "c1.vtp", "Body");
  const RunResult twice = runSliceMesh("--inputContours " + quoted(contours.string()) + " " +
                                       quoted(contours.string()) + " " + quoted((folder / "c.vtp").string()));
  EXPECT_EQ(twice.exitCode, cli::Success) << twice.err;
}

} // namespace
} // namespace slicemesh::testing

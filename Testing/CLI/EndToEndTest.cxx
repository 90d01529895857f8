// Whole runs of the executable on small generated volumes: label maps and a grayscale volume in,
// meshes, summary, return parameters and progress out.
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "ModuleDescription.h"
#include "ModuleXml.h"
#include "MeshReader.h"
#include "Measures/MeshValidation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{


/** Two boxes in a 16 x 16 x 10 label map with 1 x 1 x 2 mm voxels:
 *  label 1: i, j in [3, 9), k in [2, 6)  -> 6 x 6 x 8 mm = 288 mm^3 of voxels;
 *  label 2: i in [11, 14), j in [3, 7), k in [3, 7) -> 3 x 4 x 8 mm = 96 mm^3 of voxels. */
unsigned char twoBoxesLabel(int i, int j, int k)
{
  if (i >= 3 && i < 9 && j >= 3 && j < 9 && k >= 2 && k < 6)
    return 1;
  if (i >= 11 && i < 14 && j >= 3 && j < 7 && k >= 3 && k < 7)
    return 2;
  return 0;
}

fs::path twoBoxesLabelMap(const fs::path& folder)
{
  const fs::path path = folder / "two-boxes.mha";
  writeMetaImage(path, { 16, 16, 10 }, { 1.0, 1.0, 2.0 }, twoBoxesLabel);
  return path;
}

/** Contours at the 0.5 level cut each voxel-square corner by a right triangle of legs 0.5 voxel;
 *  the end caps are domes rising half a slice (r) on a quarter circle, each lacking about
 *  perimeter * r^2 * (1 - pi/4) of the full height. Volume of an a x b voxel box (1 mm pixels). */
double expectedBoxVolume(int a, int b, int slices, double sliceThickness)
{
  const double r = 0.5 * sliceThickness;
  const double perimeter = 2.0 * (a + b) - 4.0 + 4.0 * std::sqrt(0.5);
  return (a * b - 4 * 0.125) * slices * sliceThickness - 2.0 * perimeter * r * r * (1.0 - M_PI / 4.0);
}

/** A 3D MetaImage of MET_USHORT, MET_SHORT or MET_FLOAT voxels (`Pixel`), voxel (i, j, k) value(i, j, k). */
template <typename Pixel>
void writeMetaImageOf(const fs::path& path, std::array<int, 3> size, std::array<double, 3> spacing,
                      const std::function<Pixel(int, int, int)>& value)
{
  std::ofstream out(path, std::ios::binary);
  out << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
      << "Offset = 0 0 0\nTransformMatrix = 1 0 0 0 1 0 0 0 1\n"
      << "ElementSpacing = " << spacing[0] << " " << spacing[1] << " " << spacing[2] << "\n"
      << "DimSize = " << size[0] << " " << size[1] << " " << size[2] << "\n"
      << "ElementType = "
      << (std::is_same_v<Pixel, float> ? "MET_FLOAT" : std::is_same_v<Pixel, std::int16_t> ? "MET_SHORT" : "MET_USHORT")
      << "\nElementDataFile = LOCAL\n";
  for (int k = 0; k < size[2]; ++k)
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i)
      {
        const Pixel v = value(i, j, k);
        out.write(reinterpret_cast<const char*>(&v), sizeof v);
      }
}

std::map<std::string, std::string> returnParameterMap(const fs::path& path)
{
  std::map<std::string, std::string> map;
  for (const auto& [name, value] : returnParameters(path))
  {
    map[name] = value;
  }
  return map;
}

TEST(EndToEnd, LabelMapGivesAClosedMeshSummaryAndReturnParameters)
{
  const fs::path folder = freshFolder("e2e-labelmap");
  const fs::path output = folder / "box.vtp";
  const fs::path params = folder / "box.params";
  const RunResult r = runSliceMesh("--label 1 --returnparameterfile " + quoted(params.string()) + " " +
                                   quoted(twoBoxesLabelMap(folder).string()) + " " + quoted(output.string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_GT(fs::file_size(output), 0u);

  // The summary is the last line on stdout.
  const std::vector<std::string> lines = linesOf(r.out);
  ASSERT_FALSE(lines.empty());
  const std::string summary = lines.back();
  EXPECT_EQ(summary.rfind("SliceMesh: ", 0), 0u) << summary;
  EXPECT_NE(summary.find(" triangles, closed, volume "), std::string::npos) << summary;
  EXPECT_NE(summary.find(" mm^3 ("), std::string::npos) << summary;
  EXPECT_NE(summary.find(" mL), "), std::string::npos) << summary;

  // Exactly the return parameters the XML declares, in its order.
  std::vector<std::string> declared;
  const auto description = cli::parseModuleDescription(cli::moduleXml()); // outlives the loop's pointers
  for (const cli::ModuleParameter* p : description.parameters())
  {
    if (p->isReturnParameter())
    {
      declared.push_back(p->name);
    }
  }
  std::vector<std::string> written;
  for (const auto& entry : returnParameters(params))
  {
    written.push_back(entry.first);
  }
  EXPECT_EQ(written, declared);
  const auto values = returnParameterMap(params);
  EXPECT_GT(std::stol(values.at("triangles")), 12);
  EXPECT_EQ(values.at("closed"), "true");
  EXPECT_NEAR(std::stod(values.at("volume")), expectedBoxVolume(6, 6, 4, 2.0), 0.05 * 288.0);
  EXPECT_GE(std::stod(values.at("seconds")), 0.0);
  EXPECT_NE(summary.find(values.at("triangles") + " triangles"), std::string::npos);
}

TEST(EndToEnd, ProgressCoversEveryStageMonotonicallyFromZeroToOne)
{
  const fs::path folder = freshFolder("e2e-progress");
  const RunResult r = runSliceMesh(quoted(twoBoxesLabelMap(folder).string()) + " " +
                                   quoted((folder / "boxes.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  const std::vector<std::string> stages = { "Reading",    "Segmentation", "Contours", "Correspondence",
                                              "Tiling",     "Validation",   "Finishing", "Writing" };
  EXPECT_EQ(stageNames(r.out, "filter-start"), stages);
  EXPECT_EQ(stageNames(r.out, "filter-end"), stages);
  const std::vector<double> progress = tagNumbers(r.out, "filter-progress");
  ASSERT_FALSE(progress.empty());
  EXPECT_DOUBLE_EQ(progress.front(), 0.0);
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
  for (std::size_t i = 1; i < progress.size(); ++i)
  {
    EXPECT_GE(progress[i], progress[i - 1]);
  }
  for (double stageProgress : tagNumbers(r.out, "filter-stage-progress"))
  {
    EXPECT_GE(stageProgress, 0.0);
    EXPECT_LE(stageProgress, 1.0);
  }
  EXPECT_EQ(tagNumbers(r.out, "filter-time").size(), stages.size());
}

TEST(EndToEnd, LabelSelectsOneStructure)
{
  const fs::path folder = freshFolder("e2e-label2");
  const fs::path params = folder / "p.params";
  const RunResult r = runSliceMesh("-l 2 --returnparameterfile " + quoted(params.string()) + " " +
                                   quoted(twoBoxesLabelMap(folder).string()) + " " + quoted((folder / "b.stl").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  // The default finish gives the surface its voxels' volume: 3 x 4 x 4 voxels of 2 mm (the tiling,
  // expectedBoxVolume, cuts the box's edges and sits at 86.5 mm^3).
  EXPECT_NEAR(std::stod(returnParameterMap(params).at("volume")), 3 * 4 * 4 * 2.0, 1e-3 * 96.0);
}

TEST(EndToEnd, AbsentLabelIsAnEmptySegmentationAndLeavesTheOutputAlone)
{
  const fs::path folder = freshFolder("e2e-empty");
  const fs::path output = folder / "out.vtp";
  std::ofstream(output) << "precious";
  const RunResult r = runSliceMesh("--label 9 " + quoted(twoBoxesLabelMap(folder).string()) + " " +
                                   quoted(output.string()));
  EXPECT_EQ(r.exitCode, cli::EmptySegmentation) << r.err;
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_EQ(fileText(output), "precious");
}

TEST(EndToEnd, OutputsThroughSymbolicLinksReplaceTheFilesTheyName)
{
  // A cohort's "latest" links into a results tree: the links stay, the files they name are replaced.
  const fs::path folder = freshFolder("e2e-symlink");
  fs::create_directories(folder / "results");
  std::ofstream(folder / "results" / "b.vtp") << "an earlier mesh";
  fs::create_symlink(fs::path("results") / "b.vtp", folder / "latest.vtp");
  fs::create_symlink(folder / "results" / "b.json", folder / "latest.json"); // no report there yet
  const RunResult r = runSliceMesh("-l 2 --report " + quoted((folder / "latest.json").string()) + " " +
                                   quoted(twoBoxesLabelMap(folder).string()) + " " +
                                   quoted((folder / "latest.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  for (const std::string link : { "latest.vtp", "latest.json" })
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder / link))) << link;
  EXPECT_NE(fileText(folder / "results" / "b.vtp").find("<VTKFile"), std::string::npos);
  EXPECT_NE(fileText(folder / "results" / "b.json").find("\"triangles\""), std::string::npos);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder / "results"), fs::directory_iterator()), 2)
    << "no temporary files";
}

TEST(EndToEnd, ReplacedOutputsKeepTheirPermissions)
{
  // A mesh and a report kept private (0600) stay so once replaced; the one-mesh and the multi-label
  // runs write them differently (one file, files committed together).
  const fs::path folder = freshFolder("e2e-permissions");
  const fs::perms ownerOnly = fs::perms::owner_read | fs::perms::owner_write;
  const auto permissionsOf = [](const fs::path& path) { return fs::status(path).permissions() & fs::perms::all; };
  for (const std::string& run : { "-l 2", "--splitLabels" })
  {
    for (const std::string name : { "out.vtp", "report.json" })
    {
      std::ofstream(folder / name) << "an earlier run's";
      fs::permissions(folder / name, ownerOnly);
    }
    const RunResult r = runSliceMesh(run + " --report " + quoted((folder / "report.json").string()) + " " +
                                     quoted(twoBoxesLabelMap(folder).string()) + " " + quoted((folder / "out.vtp").string()));
    ASSERT_EQ(r.exitCode, cli::Success) << r.err;
    EXPECT_NE(fileText(folder / "out.vtp"), "an earlier run's") << run;
    EXPECT_EQ(permissionsOf(folder / "out.vtp"), ownerOnly) << run;
    EXPECT_EQ(permissionsOf(folder / "report.json"), ownerOnly) << run;
  }
}

TEST(EndToEnd, GrayscaleWithOtsuFindsTheBrightObject)
{
  const fs::path folder = freshFolder("e2e-grayscale");
  const fs::path input = folder / "bright-box.mha";
  writeMetaImage(input, { 16, 16, 10 }, { 1.0, 1.0, 2.0 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   const bool inside = i >= 3 && i < 9 && j >= 3 && j < 9 && k >= 2 && k < 6;
                   return static_cast<unsigned char>(inside ? 200 + (i + j) % 5 : 20 + (i * j + k) % 7);
                 });
  const fs::path params = folder / "p.params";
  const RunResult r = runSliceMesh("--inputKind Grayscale --returnparameterfile " + quoted(params.string()) + " " +
                                   quoted(input.string()) + " " + quoted((folder / "box.ply").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NEAR(std::stod(returnParameterMap(params).at("volume")), expectedBoxVolume(6, 6, 4, 2.0), 0.05 * 288.0);
}

/** The "v x y z" lines of an OBJ file. */
std::vector<std::array<double, 3>> objVertices(const fs::path& path)
{
  std::vector<std::array<double, 3>> vertices;
  for (const std::string& line : linesOf(fileText(path)))
  {
    if (line.rfind("v ", 0) == 0)
    {
      std::istringstream in(line.substr(2));
      std::array<double, 3> v{};
      in >> v[0] >> v[1] >> v[2];
      vertices.push_back(v);
    }
  }
  return vertices;
}

TEST(EndToEnd, RASOutputNegatesXAndYAndSaysSo)
{
  const fs::path folder = freshFolder("e2e-ras");
  const fs::path input = twoBoxesLabelMap(folder);
  const fs::path lps = folder / "lps.obj";
  const fs::path ras = folder / "ras.obj";
  ASSERT_EQ(runSliceMesh("-l 1 " + quoted(input.string()) + " " + quoted(lps.string())).exitCode, cli::Success);
  ASSERT_EQ(runSliceMesh("-l 1 --coordinateSystem RAS " + quoted(input.string()) + " " + quoted(ras.string())).exitCode,
            0);
  EXPECT_NE(fileText(lps).find("SPACE=LPS"), std::string::npos);
  EXPECT_NE(fileText(ras).find("SPACE=RAS"), std::string::npos);
  const auto a = objVertices(lps);
  const auto b = objVertices(ras);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_DOUBLE_EQ(b[i][0], -a[i][0]);
    EXPECT_DOUBLE_EQ(b[i][1], -a[i][1]);
    EXPECT_DOUBLE_EQ(b[i][2], a[i][2]);
  }
}

TEST(EndToEnd, SameInputGivesTheSameFileBitForBit)
{
  const fs::path folder = freshFolder("e2e-deterministic");
  const fs::path input = twoBoxesLabelMap(folder);
  ASSERT_EQ(runSliceMesh(quoted(input.string()) + " " + quoted((folder / "a.obj").string())).exitCode, cli::Success);
  ASSERT_EQ(runSliceMesh(quoted(input.string()) + " " + quoted((folder / "b.obj").string())).exitCode, cli::Success);
  EXPECT_EQ(fileText(folder / "a.obj"), fileText(folder / "b.obj"));
}

/** The two boxes of twoBoxesLabelMap with one-voxel specks (2 mm^3 each, touching nothing, not
 *  even at a corner): label 1 gets one, label 2 two, and label 3 is a speck only. */
fs::path boxesWithSpecksLabelMap(const fs::path& folder)
{
  const fs::path path = folder / "boxes-and-specks.mha";
  writeMetaImage(path, { 16, 16, 10 }, { 1.0, 1.0, 2.0 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   if (const unsigned char box = twoBoxesLabel(i, j, k))
                     return box;
                   if (i == 14 && j == 14 && k == 8)
                     return 1;
                   if ((i == 1 && j == 14 && k == 1) || (i == 14 && j == 1 && k == 8))
                     return 2;
                   if (i == 1 && j == 1 && k == 8)
                     return 3;
                   return 0;
                 });
  return path;
}

/** The text of a multi-label report's entry for one label (from its "label" key to the next). */
std::string labelEntry(const std::string& report, int label)
{
  const std::string key = "\"label\": " + std::to_string(label) + ",";
  const std::size_t begin = report.find(key);
  if (begin == std::string::npos)
    return "";
  return report.substr(begin, report.find("\"label\": ", begin + key.size()) - begin);
}

TEST(EndToEnd, MultiLabelDropsComponentsUnderTheMinimumVolume)
{
  const fs::path folder = freshFolder("e2e-multilabel-specks");
  const fs::path input = boxesWithSpecksLabelMap(folder);

  // Without the option every speck is meshed: 2 + 3 + 1 components, label 3 has a file.
  const RunResult all = runSliceMesh("--outputDirectory " + quoted((folder / "all").string()) + " " +
                                     quoted(input.string()) + " " + quoted((folder / "all.vtp").string()));
  ASSERT_EQ(all.exitCode, cli::Success) << all.err;
  EXPECT_NE(linesOf(all.out).back().find("6 components"), std::string::npos) << linesOf(all.out).back();
  EXPECT_TRUE(fs::exists(folder / "all" / "003_Label_3.vtp"));

  // With it (10 mm^3: five voxels) the specks go, as in the single-label path: one box per label,
  // label 3 is dropped with a warning and no file, and the report says what was removed.
  const fs::path report = folder / "kept.json";
  const RunResult kept =
    runSliceMesh("--minimumComponentVolume 10 --report " + quoted(report.string()) + " --outputDirectory " +
                 quoted((folder / "kept").string()) + " " + quoted(input.string()) + " " +
                 quoted((folder / "kept.vtp").string()));
  ASSERT_EQ(kept.exitCode, cli::Success) << kept.err;
  EXPECT_NE(linesOf(kept.out).back().find("2 components"), std::string::npos) << linesOf(kept.out).back();
  EXPECT_NE(kept.err.find("label 3 (Label_3) dropped"), std::string::npos) << kept.err;
  EXPECT_TRUE(fs::exists(folder / "kept" / "001_Label_1.vtp"));
  EXPECT_TRUE(fs::exists(folder / "kept" / "002_Label_2.vtp"));
  EXPECT_FALSE(fs::exists(folder / "kept" / "003_Label_3.vtp"));
  const std::string json = fileText(report);
  EXPECT_NE(labelEntry(json, 1).find("\"removedComponents\": 1,"), std::string::npos) << labelEntry(json, 1);
  EXPECT_NE(labelEntry(json, 1).find("\"components\": 1,"), std::string::npos) << labelEntry(json, 1);
  EXPECT_NE(labelEntry(json, 2).find("\"removedComponents\": 2,"), std::string::npos) << labelEntry(json, 2);
  EXPECT_NE(labelEntry(json, 3).find("\"dropped\": true"), std::string::npos) << labelEntry(json, 3);
  EXPECT_EQ(labelEntry(json, 3).find("\"mesh\""), std::string::npos) << labelEntry(json, 3);

  // When the option removes every label there is nothing to mesh: exit 4, nothing written.
  const fs::path output = folder / "none.vtp";
  const RunResult none = runSliceMesh("--minimumComponentVolume 1000 --outputDirectory " +
                                      quoted((folder / "none").string()) + " " + quoted(input.string()) + " " +
                                      quoted(output.string()));
  EXPECT_EQ(none.exitCode, cli::EmptySegmentation) << none.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_FALSE(fs::exists(folder / "none")) << "the folder the failed run made is removed again";
  // A folder the user had stays, empty as it was.
  fs::create_directory(folder / "theirs");
  EXPECT_EQ(runSliceMesh("--minimumComponentVolume 1000 --outputDirectory " + quoted((folder / "theirs").string()) +
                         " " + quoted(input.string()) + " " + quoted(output.string()))
              .exitCode,
            cli::EmptySegmentation);
  EXPECT_TRUE(fs::is_directory(folder / "theirs"));
  // Of nested folders the run made, each is removed; the one it found is kept.
  EXPECT_EQ(runSliceMesh("--outputDirectory " + quoted((folder / "theirs" / "a" / "b").string()) + " " +
                         quoted((folder / "missing.nrrd").string()) + " " + quoted(output.string()))
              .exitCode,
            cli::UnreadableInput);
  EXPECT_FALSE(fs::exists(folder / "theirs" / "a"));
  EXPECT_TRUE(fs::is_directory(folder / "theirs"));
}

TEST(EndToEnd, AMaskOfManySpecksIsMeshedWithAHintToDropThem)
{
  // A block and 1304 single voxels three apart around it, as a threshold of a noisy image leaves:
  // the run says most pieces are specks and names the options that remove them.
  const fs::path folder = freshFolder("e2e-speck-noise");
  const fs::path input = folder / "block-in-noise.mha";
  // The block spans voxels 12 to 19: the lattice's nearest points outside it (9 and 21) are a voxel off.
  auto inBlock = [](int i, int j, int k) { return i >= 12 && i < 20 && j >= 12 && j < 20 && k >= 12 && k < 20; };
  writeMetaImage(input, { 33, 33, 33 }, { 1.0, 1.0, 1.0 },
                 [&](int i, int j, int k) -> unsigned char
                 {
                   if (inBlock(i, j, k))
                     return 1;
                   const bool lattice = i % 3 == 0 && j % 3 == 0 && k % 3 == 0;
                   return lattice ? 1 : 0;
                 });
  const RunResult noisy = runSliceMesh(quoted(input.string()) + " " + quoted((folder / "noisy.vtp").string()));
  ASSERT_EQ(noisy.exitCode, cli::Success) << noisy.err;
  const std::size_t at = noisy.err.find(" pieces are specks of a few voxels");
  ASSERT_NE(at, std::string::npos) << noisy.err;
  const std::string line = noisy.err.substr(noisy.err.rfind("warning: ", at), at - noisy.err.rfind("warning: ", at));
  std::size_t specks = 0, pieces = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "warning: %zu of the %zu", &specks, &pieces), 2) << line;
  EXPECT_GE(specks, 1000u);
  EXPECT_EQ(pieces, specks + 1) << "the block is the one piece not a speck";
  EXPECT_NE(noisy.err.find("--minimumComponentVolume"), std::string::npos);
  // The specks dropped first: the block alone, no hint.
  const RunResult clean = runSliceMesh("--minimumComponentVolume 2 " + quoted(input.string()) + " " +
                                       quoted((folder / "clean.vtp").string()));
  ASSERT_EQ(clean.exitCode, cli::Success) << clean.err;
  EXPECT_EQ(clean.err.find("specks"), std::string::npos) << clean.err;
  EXPECT_NE(linesOf(clean.out).back().find(" 1 component,"), std::string::npos) << linesOf(clean.out).back();
}

TEST(EndToEnd, MeshFilesOfAnEarlierRunInTheFolderAreSaidAndKept)
{
  const fs::path folder = freshFolder("e2e-earlier-files");
  const fs::path input = boxesWithSpecksLabelMap(folder);
  const std::string meshes = quoted((folder / "meshes").string());
  ASSERT_EQ(runSliceMesh("--outputDirectory " + meshes + " " + quoted(input.string()) + " " +
                         quoted((folder / "all.vtp").string()))
              .exitCode,
            cli::Success);
  std::ofstream(folder / "meshes" / "notes.txt") << "the user's"; // not named as a mesh: not counted
  const RunResult one = runSliceMesh("--labels 1 --outputDirectory " + meshes + " " + quoted(input.string()) + " " +
                                     quoted((folder / "one.vtp").string()));
  ASSERT_EQ(one.exitCode, cli::Success) << one.err;
  EXPECT_NE(one.err.find("also holds 2 mesh file(s) this run did not write (first: 002_Label_2.vtp)"), std::string::npos)
    << one.err;
  EXPECT_TRUE(fs::exists(folder / "meshes" / "003_Label_3.vtp"));
  // Into a folder of its own files only, nothing is said.
  const RunResult again = runSliceMesh("--outputDirectory " + meshes + " " + quoted(input.string()) + " " +
                                       quoted((folder / "all.vtp").string()));
  ASSERT_EQ(again.exitCode, cli::Success) << again.err;
  EXPECT_EQ(again.err.find("did not write"), std::string::npos) << again.err;
  // Another format beside them: the earlier .vtp files are said too (they were passed over).
  const RunResult stl = runSliceMesh("--outputDirectory " + meshes + " " + quoted(input.string()) + " " +
                                     quoted((folder / "all.stl").string()));
  ASSERT_EQ(stl.exitCode, cli::Success) << stl.err;
  EXPECT_NE(stl.err.find("mesh file(s) this run did not write (first: 001_Label_1.vtp)"), std::string::npos) << stl.err;
}

TEST(EndToEnd, LabelsPastFloatsPrecisionStayApart)
{
  // Atlases such as the Allen mouse brain's number their structures up to hundreds of millions, in
  // four-byte integers. Read as float, 16777216 and 16777217 were one label and 33554435 was named
  // 33554436. Four boxes of 4 x 4 x 4 voxels (1 mm), one per label.
  const fs::path folder = freshFolder("e2e-large-labels");
  const fs::path input = folder / "labels.mha";
  const std::array<std::uint32_t, 4> labels{ 16777216u, 16777217u, 33554435u, 614454277u };
  {
    std::ofstream out(input, std::ios::binary);
    out << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
        << "ElementSpacing = 1 1 1\nDimSize = 26 8 8\nElementType = MET_UINT\nElementDataFile = LOCAL\n";
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 26; ++i)
        {
          const bool inside = (i - 2) % 6 < 4 && i >= 2 && j >= 2 && j < 6 && k >= 2 && k < 6;
          const std::uint32_t value = inside ? labels[static_cast<std::size_t>((i - 2) / 6)] : 0u;
          for (int byte = 0; byte < 4; ++byte)
            out.put(static_cast<char>((value >> (8 * byte)) & 0xffu));
        }
  }
  const fs::path report = folder / "r.json";
  const RunResult all = runSliceMesh("--report " + quoted(report.string()) + " --outputDirectory " +
                                     quoted((folder / "meshes").string()) + " " + quoted(input.string()) + " " +
                                     quoted((folder / "all.vtp").string()));
  ASSERT_EQ(all.exitCode, cli::Success) << all.err;
  const std::string json = fileText(report);
  for (const std::uint32_t label : labels)
  {
    const std::string entry = labelEntry(json, static_cast<int>(label));
    ASSERT_FALSE(entry.empty()) << label << " missing from " << json.substr(0, 2000);
    EXPECT_NE(entry.find("\"voxels\": 64,"), std::string::npos) << entry.substr(0, 300);
    char name[64];
    std::snprintf(name, sizeof name, "%09u_Label_%u.vtp", label, label); // padded to the largest's digits
    EXPECT_TRUE(fs::exists(folder / "meshes" / name)) << name;
  }
  // One of two neighbouring labels picked alone: its box, not both.
  const RunResult one = runSliceMesh("--label 16777217 " + quoted(input.string()) + " " + quoted((folder / "one.vtp").string()));
  ASSERT_EQ(one.exitCode, cli::Success) << one.err;
  const std::string summary = linesOf(one.out).back();
  ASSERT_NE(summary.find(", 1 component,"), std::string::npos) << summary;
  EXPECT_NE(summary.find(" triangles, closed, "), std::string::npos) << summary;
  EXPECT_NE(summary.find(", manifold, no self-intersections"), std::string::npos) << summary;
  const std::size_t at = summary.find(", volume ");
  ASSERT_NE(at, std::string::npos) << summary;
  EXPECT_NEAR(std::stod(summary.substr(at + 9)), 64.0, 0.02 * 64.0) << summary;
}

TEST(EndToEnd, SummaryVolumeOfATinyStructureIsNotRoundedToZero)
{
  // A 4 x 4 x 4 voxel cube at 10 micrometres (a micro-CT's grid): 6.4e-5 mm^3.
  const fs::path folder = freshFolder("e2e-tiny-volume");
  const fs::path input = folder / "cube.mha";
  writeMetaImage(input, { 8, 8, 8 }, { 0.01, 0.01, 0.01 },
                 [](int i, int j, int k) { return i >= 2 && i < 6 && j >= 2 && j < 6 && k >= 2 && k < 6 ? 1 : 0; });
  const RunResult r = runSliceMesh(quoted(input.string()) + " " + quoted((folder / "cube.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  const std::string summary = linesOf(r.out).back();
  const std::size_t at = summary.find(", volume ");
  ASSERT_NE(at, std::string::npos) << summary;
  const double volume = std::stod(summary.substr(at + 9));
  EXPECT_NEAR(volume, 6.4e-5, 0.2 * 6.4e-5) << summary;
}

/** A number that follows `"key": ` in a JSON text (the first occurrence after `from`); NaN if none. */
double jsonNumberAfter(const std::string& json, const std::string& key, std::size_t from = 0)
{
  const std::size_t at = json.find("\"" + key + "\": ", from);
  return at == std::string::npos ? std::nan("") : std::stod(json.substr(at + key.size() + 4));
}

TEST(EndToEnd, MultiLabelSummaryAndReportCarryRealQuality)
{
  const fs::path folder = freshFolder("e2e-multilabel-quality");
  const fs::path report = folder / "quality.json";
  // Label 1 a stepped pyramid (each slice one voxel smaller all round: sloped tilings, a non-zero
  // Dirichlet energy), label 2 a box (vertical walls only: zero energy).
  const fs::path input = folder / "pyramid-and-box.mha";
  writeMetaImage(input, { 16, 16, 10 }, { 1.0, 1.0, 2.0 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   const int s = k - 2;
                   if (k >= 2 && k < 5 && i >= 2 + s && i < 10 - s && j >= 2 + s && j < 10 - s)
                     return 1;
                   if (i >= 11 && i < 14 && j >= 3 && j < 7 && k >= 3 && k < 7)
                     return 2;
                   return 0;
                 });
  const RunResult r = runSliceMesh("--splitLabels --report " + quoted(report.string()) + " " + quoted(input.string()) +
                                   " " + quoted((folder / "labels.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  // Without an output folder the labels' meshes are in the model alone: said, and no other file.
  EXPECT_NE(r.out.find("the 2 labels' meshes are in '" + (folder / "labels.vtp").string() + "' alone"), std::string::npos)
    << r.out;
  std::size_t files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    files += entry.path().extension() == ".vtp";
  EXPECT_EQ(files, 1u);
  const std::string summary = linesOf(r.out).back();
  // Two solids: genus 0 each, angles of real triangles, 1 mm points on 2 mm slices.
  EXPECT_NE(summary.find("2 components"), std::string::npos) << summary;
  // The labels are checked each on its own: they may touch or cross each other.
  EXPECT_NE(summary.find("no self-intersections within a structure"), std::string::npos) << summary;
  EXPECT_NE(summary.find("genus 0,"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("min angle 0.0 deg"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("point/slice spacing 0.00"), std::string::npos) << summary;
  EXPECT_NE(summary.find("stages Reading"), std::string::npos) << summary;

  const std::string json = fileText(report);
  const std::string first = labelEntry(json, 1), second = labelEntry(json, 2);
  ASSERT_FALSE(first.empty()) << json;
  ASSERT_FALSE(second.empty()) << json;
  // The whole run: the smallest angle is the smaller of the labels', the energy their sum, the
  // spacing ratio between theirs, the volume their sum.
  const double minAngle1 = jsonNumberAfter(first, "minAngleDegrees"), minAngle2 = jsonNumberAfter(second, "minAngleDegrees");
  EXPECT_GT(minAngle1, 0.0);
  EXPECT_GT(minAngle2, 0.0);
  EXPECT_DOUBLE_EQ(jsonNumberAfter(json, "minAngleDegrees"), std::min(minAngle1, minAngle2));
  EXPECT_NEAR(jsonNumberAfter(json, "energyMm2"),
              jsonNumberAfter(first, "energyMm2") + jsonNumberAfter(second, "energyMm2"), 1e-6);
  EXPECT_GT(jsonNumberAfter(first, "energyMm2"), 0.0);
  EXPECT_EQ(jsonNumberAfter(second, "energyMm2"), 0.0);
  const double ratio = jsonNumberAfter(json, "pointToSliceSpacingRatio");
  EXPECT_GT(ratio, 0.3);
  EXPECT_LE(ratio, std::max(jsonNumberAfter(first, "pointToSliceSpacingRatio"),
                            jsonNumberAfter(second, "pointToSliceSpacingRatio")) + 1e-9);
  EXPECT_EQ(jsonNumberAfter(json, "genus"), 0.0);
  // The remeshed 3 x 4 x 4 voxel box encloses its voxels' volume (see LabelSelectsOneStructure).
  EXPECT_NEAR(jsonNumberAfter(second, "volumeMm3"), 3 * 4 * 4 * 2.0, 1e-3 * 96.0);
  EXPECT_NEAR(jsonNumberAfter(json, "volumeMm3"),
              jsonNumberAfter(first, "volumeMm3") + jsonNumberAfter(second, "volumeMm3"), 1e-6);
  // The combined model's "valid" and self-intersection figures are the labels' own: the report
  // says so (labels that touch may intersect each other, which is not checked).
  const std::string top = json.substr(0, json.find("\"labels\": ["));
  EXPECT_NE(top.find("\"validatedAs\": \"eachStructure\""), std::string::npos) << top;
  EXPECT_NE(top.find("\"validationNote\": \"the figures sum those of each structure's mesh, checked on its own; "
                     "meshes of different structures may touch or intersect each other (not checked)\""),
            std::string::npos)
    << top;
  for (const std::string& entry : { first, second })
  {
    EXPECT_NE(entry.find("\"validatedAs\": \"wholeMesh\""), std::string::npos) << entry;
    EXPECT_EQ(entry.find("validationNote"), std::string::npos) << entry;
  }
}

/** An ellipse (semi-axes 7 x 2.6 mm) sliding 4 mm along its long axis from slice to slice over
 *  four 3 mm slices: consecutive slices' regions overlap by 66% of either (counted on the voxels),
 *  less than the default section overlap (80%) but more than 60%. */
fs::path slidingEllipse(const fs::path& folder)
{
  const fs::path path = folder / "sliding-ellipse.mha";
  writeMetaImage(path, { 40, 14, 7 }, { 1.0, 1.0, 3.0 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   if (k < 1 || k > 4)
                     return 0;
                   const double x = (i - 9.0 - 4.0 * (k - 1)) / 7.0, y = (j - 7.0) / 2.6;
                   return x * x + y * y <= 1.0 ? 1 : 0;
                 });
  return path;
}

TEST(EndToEnd, RefineWeakOverlapAndSectionOverlapReachTheSections)
{
  const fs::path folder = freshFolder("e2e-section-overlap");
  const fs::path input = slidingEllipse(folder);
  struct Mesh
  {
    double triangles = 0.0, volume = 0.0;
  };
  // The sections show in the tiling (its rows of triangles): pinned to it, since a remeshed
  // surface's triangle count follows its area, not the sections.
  auto mesh = [&](const std::string& name, const std::string& options)
  {
    const fs::path params = folder / (name + ".params");
    const RunResult r = runSliceMesh(options + " --surfaceFinish Tiled --returnparameterfile " + quoted(params.string()) + " " +
                                     quoted(input.string()) + " " + quoted((folder / (name + ".vtp")).string()));
    EXPECT_EQ(r.exitCode, cli::Success) << name << ": " << r.err;
    EXPECT_EQ(r.err, "") << name;
    std::map<std::string, std::string> values = returnParameterMap(params);
    EXPECT_EQ(values["closed"], "true") << name;
    return Mesh{ std::stod(values["triangles"]), std::stod(values["volume"]) };
  };
  const Mesh plain = mesh("plain", "");
  // 66% overlap is not weak against 0.6: no slab gets sections, the mesh is the plain one.
  const Mesh notWeak = mesh("not-weak", "--refineWeakOverlap --sectionOverlap 0.6");
  EXPECT_EQ(notWeak.triangles, plain.triangles);
  EXPECT_EQ(notWeak.volume, plain.volume);
  // Against the default 0.8 every slab gets sections: more rows of triangles, and the volume the
  // tiling between partly overlapping contours loses comes back (measured: +2.7%).
  const Mesh refined = mesh("refined", "--refineWeakOverlap");
  EXPECT_GT(refined.triangles, plain.triangles);
  EXPECT_GT(refined.volume, 1.015 * plain.volume);
  // A higher share asks for more sections per slab.
  const Mesh finer = mesh("finer", "--refineWeakOverlap --sectionOverlap 0.95");
  EXPECT_GT(finer.triangles, refined.triangles);
  EXPECT_GE(finer.volume, refined.volume);
}

TEST(EndToEnd, MultiLabelAppliesTheCorrespondenceOptions)
{
  // The per-label meshes go through the same correspondence stage as the single mesh (seen in the
  // tiling's triangles, so pinned to it as in RefineWeakOverlapAndSectionOverlapReachTheSections).
  const fs::path folder = freshFolder("e2e-multilabel-sections");
  const fs::path input = slidingEllipse(folder);
  auto triangles = [&](const std::string& name, const std::string& options)
  {
    const fs::path params = folder / (name + ".params");
    const RunResult r = runSliceMesh("--splitLabels --surfaceFinish Tiled " + options + " --returnparameterfile " + quoted(params.string()) +
                                     " " + quoted(input.string()) + " " + quoted((folder / (name + ".vtp")).string()));
    EXPECT_EQ(r.exitCode, cli::Success) << name << ": " << r.err;
    std::map<std::string, std::string> values = returnParameterMap(params);
    EXPECT_EQ(values["closed"], "true") << name;
    return std::stod(values["triangles"]);
  };
  EXPECT_GT(triangles("refined", "--refineWeakOverlap"), triangles("plain", ""));
}

TEST(EndToEnd, SectionOverlapWithoutAnyUseWarns)
{
  const fs::path folder = freshFolder("e2e-section-overlap-unused");
  const RunResult r = runSliceMesh("--label 1 --sectionOverlap 0.5 " + quoted(twoBoxesLabelMap(folder).string()) + " " +
                                   quoted((folder / "box.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_EQ(linesOf(r.err), std::vector<std::string>{ "SliceMesh: warning: --sectionOverlap is used only with "
                                                      "--bridgeNonOverlapping or --refineWeakOverlap; it has no effect" });
}

TEST(EndToEnd, MultiLabelSnapshotShowsEveryLabel)
{
  // The picture needs an X display: a virtual one from xvfb-run (package xvfb, in the installer).
  if (runCommand("command -v xvfb-run").exitCode != 0)
    GTEST_SKIP() << "xvfb-run is not installed";
  const fs::path folder = freshFolder("e2e-multilabel-snapshot");
  const fs::path png = folder / "labels.png";
  const RunResult r =
    runCommand("xvfb-run -a " + quoted(SLICEMESH_EXECUTABLE) + " --splitLabels --snapshot " + quoted(png.string()) +
               " " + quoted(twoBoxesLabelMap(folder).string()) + " " + quoted((folder / "boxes.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  ASSERT_TRUE(fs::exists(png));
  // A PNG of the default size: the signature, then the IHDR chunk's big-endian width and height.
  const std::string bytes = fileText(png);
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  auto bigEndian = [&](std::size_t at)
  {
    unsigned value = 0;
    for (std::size_t n = 0; n < 4; ++n)
      value = (value << 8) | static_cast<unsigned char>(bytes[at + n]);
    return value;
  };
  EXPECT_EQ(bigEndian(16), 800u);
  EXPECT_EQ(bigEndian(20), 600u);

  // Without a display the run fails at once, writing nothing.
  const fs::path output = folder / "no-display.vtp";
  const RunResult noDisplay = runCommand("env -u DISPLAY " + quoted(SLICEMESH_EXECUTABLE) + " --splitLabels --snapshot " +
                                         quoted((folder / "no.png").string()) + " " +
                                         quoted((folder / "two-boxes.mha").string()) + " " + quoted(output.string()));
  EXPECT_EQ(noDisplay.exitCode, cli::WriteFailed) << noDisplay.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_FALSE(fs::exists(folder / "no.png"));
}

TEST(EndToEnd, SnapshotWithoutDisplayFailsBeforeAnyWorkOnBothPaths)
{
  // No xvfb-run and DISPLAY unset: the single-label path must fail as the multi-label one does,
  // before reading the volume (no progress stage starts) and before writing anything.
  const fs::path folder = freshFolder("e2e-snapshot-no-display");
  const fs::path input = twoBoxesLabelMap(folder);
  const fs::path png = folder / "picture.png";
  auto runWithoutDisplay = [&](const std::string& options, const fs::path& output)
  {
    return runCommand("env -u DISPLAY " + quoted(SLICEMESH_EXECUTABLE) + " " + options + " --snapshot " +
                      quoted(png.string()) + " " + quoted(input.string()) + " " + quoted(output.string()));
  };
  const RunResult single = runWithoutDisplay("--label 1", folder / "single.vtp");
  const RunResult multi = runWithoutDisplay("--splitLabels", folder / "multi.vtp");
  const std::string expected =
    "SliceMesh: error: cannot render snapshot '" + png.string() + "': no X display (DISPLAY is not set); run under xvfb-run";
  for (const RunResult* r : { &single, &multi })
  {
    EXPECT_EQ(r->exitCode, cli::WriteFailed) << r->err;
    EXPECT_EQ(linesOf(r->err), std::vector<std::string>{ expected });
    EXPECT_TRUE(stageNames(r->out, "filter-start").empty()) << r->out;
  }
  // Only the input is left in the folder: no mesh, no picture, no temporary file.
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    files.push_back(entry.path().filename().string());
  EXPECT_EQ(files, std::vector<std::string>{ input.filename().string() });
}

TEST(EndToEnd, LabelsAboveOneByteAreMeshedAsFromFloat)
{
  // A label map of 2-byte labels is read as stored (2 bytes a voxel, not float's 4): labels above
  // 255 keep their values, and each is meshed exactly as from the same labels stored as float.
  const fs::path folder = freshFolder("e2e-wide-labels");
  const auto label = [](int i, int j, int k) -> int
  {
    if (i >= 2 && i < 8 && j >= 2 && j < 9 && k >= 1 && k < 5)
      return 300;
    if (i >= 10 && i < 14 && j >= 4 && j < 12 && k >= 2 && k < 7)
      return 40000;
    return 0;
  };
  writeMetaImageOf<std::uint16_t>(folder / "wide.mha", { 16, 16, 9 }, { 0.9, 0.9, 2.0 },
                                  [&](int i, int j, int k) { return static_cast<std::uint16_t>(label(i, j, k)); });
  writeMetaImageOf<float>(folder / "wide-float.mha", { 16, 16, 9 }, { 0.9, 0.9, 2.0 },
                          [&](int i, int j, int k) { return static_cast<float>(label(i, j, k)); });
  const fs::path report = folder / "report.json";
  const RunResult stored = runSliceMesh("--splitLabels --report " + quoted(report.string()) + " " +
                                        quoted((folder / "wide.mha").string()) + " " + quoted((folder / "stored.obj").string()));
  ASSERT_EQ(stored.exitCode, cli::Success) << stored.err;
  const RunResult asFloat = runSliceMesh("--splitLabels " + quoted((folder / "wide-float.mha").string()) + " " +
                                         quoted((folder / "float.obj").string()));
  ASSERT_EQ(asFloat.exitCode, cli::Success) << asFloat.err;
  const std::string json = fileText(report);
  EXPECT_FALSE(labelEntry(json, 300).empty()) << json;
  EXPECT_FALSE(labelEntry(json, 40000).empty()) << json;
  EXPECT_NE(linesOf(stored.out).back().find("2 components"), std::string::npos) << stored.out;
  const std::string mesh = fileText(folder / "stored.obj");
  EXPECT_FALSE(mesh.empty());
  EXPECT_EQ(mesh, fileText(folder / "float.obj"));
}

TEST(EndToEnd, ContourSimplificationKeepsAOneVoxelThinBarASolid)
{
  // A bar one voxel (0.5 mm) thick and six long in one slice: at a tolerance of 0.25 mm and over,
  // every traced point is within it of the bar's axis, and the contour once fell to a triangle
  // that meshed as a flat sheet (exit 7).
  const fs::path folder = freshFolder("e2e-thin-bar");
  const fs::path input = folder / "thin-bar.mha";
  writeMetaImage(input, { 12, 8, 8 }, { 1.0, 0.5, 0.5 },
                 [](int i, int j, int k) -> unsigned char { return j == 3 && i >= 2 && i <= 7 && k == 2; });
  for (const std::string tolerance : { "0.2", "0.3", "2" })
  {
    const RunResult r = runSliceMesh("--contourSimplification " + tolerance + " " + quoted(input.string()) + " " +
                                     quoted((folder / "bar.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << tolerance << ": " << r.err;
    EXPECT_EQ(r.err, "") << tolerance;
  }
}

TEST(EndToEnd, AnAutomaticInputKindIsSaidWithItsReason)
{
  // A cube of -1 in zeros, stored as int16: read as grayscale (a voxel is negative), so Otsu meshed
  // the background without a word. The run now says which kind it chose from the voxels and why.
  const fs::path folder = freshFolder("e2e-input-kind");
  const fs::path input = folder / "negative.mha";
  writeMetaImageOf<std::int16_t>(input, { 10, 10, 10 }, { 1.0, 1.0, 1.0 }, [](int i, int j, int k) -> std::int16_t
                                 { return i >= 2 && i < 8 && j >= 2 && j < 8 && k >= 2 && k < 8 ? -1 : 0; });
  const fs::path output = folder / "out.vtp";
  RunResult r = runSliceMesh(quoted(input.string()) + " " + quoted(output.string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  std::vector<std::string> lines = linesOf(r.out);
  ASSERT_GE(lines.size(), 2u) << r.out;
  EXPECT_EQ(lines[lines.size() - 2],
            "SliceMesh: input kind Grayscale, chosen from the voxels: a voxel is negative (-1) "
            "(--inputKind LabelMap meshes its non-zero voxels instead)");

  // As the line says: the cube.
  r = runSliceMesh("--inputKind LabelMap --returnparameterfile " + quoted((folder / "cube.params").string()) + " " +
                   quoted(input.string()) + " " + quoted(output.string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_EQ(r.out.find("input kind"), std::string::npos) << "asked for, not chosen: " << r.out;
  EXPECT_NEAR(std::stod(returnParameterMap(folder / "cube.params").at("volume")), 216.0, 0.05 * 216.0);

  // A label map chosen from the voxels says so too.
  r = runSliceMesh(quoted(twoBoxesLabelMap(folder).string()) + " " + quoted(output.string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  lines = linesOf(r.out);
  ASSERT_GE(lines.size(), 2u) << r.out;
  EXPECT_EQ(lines[lines.size() - 2], "SliceMesh: input kind LabelMap, chosen from the voxels: 3 whole non-negative "
                                     "values, 0 to 2 (--inputKind Grayscale thresholds it instead)");
}

TEST(EndToEnd, AMeshThatEnclosesLessThanItsVoxelsSaysSo)
{
  // A speck follows its voxels' volume only half way (its few triangles cannot hold it): a single
  // voxel meshes as 0.24 mm^3. A volumetry user read that only in a report, beside no voxel count.
  const fs::path folder = freshFolder("e2e-volume-shortfall");
  const fs::path specks = folder / "specks.mha";
  // Twenty single voxels, each its own label, three voxels apart (1 mm).
  writeMetaImageOf<std::uint16_t>(specks, { 20, 8, 8 }, { 1.0, 1.0, 1.0 }, [](int i, int j, int k) -> std::uint16_t
                                  { return i % 4 == 1 && j % 4 == 1 && k == 3 ? static_cast<std::uint16_t>(1 + i / 4 + 5 * (j / 4)) : 0; });
  const fs::path report = folder / "specks.json";
  RunResult r = runSliceMesh("--splitLabels --report " + quoted(report.string()) + " " + quoted(specks.string()) + " " +
                             quoted((folder / "specks.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("SliceMesh: 10 of the 10 meshes enclose more than 5% more or less than their voxels; the "
                       "first, label 1 (Label_1), encloses 0."),
            std::string::npos)
    << r.out;
  EXPECT_NE(fileText(report).find("\"targetVolumeMm3\": 10"), std::string::npos) << fileText(report);
  // One mesh of one voxel says it of itself.
  const fs::path one = folder / "one.mha";
  writeMetaImage(one, { 5, 5, 5 }, { 1.0, 1.0, 1.0 }, [](int i, int j, int k) -> unsigned char { return i == 2 && j == 2 && k == 2; });
  r = runSliceMesh(quoted(one.string()) + " " + quoted((folder / "one.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("SliceMesh: the mesh encloses 0."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("less than the 1.0 mm^3 of its voxels"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "") << "a note, not a warning: Slicer marks a run that writes to stderr as failing";
  // Boxes get their voxels' volume: nothing to say.
  r = runSliceMesh(quoted(twoBoxesLabelMap(folder).string()) + " " + quoted((folder / "boxes.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_EQ(r.out.find("of its voxels"), std::string::npos) << r.out;
}

TEST(EndToEnd, AnMRIOfWholeValuesIsGrayscaleAndGrayscaleOptionsChooseGrayscale)
{
  // An MR stored as whole non-negative numbers (any 8- or 16-bit scan) was taken for a label map of
  // its intensities: the default run meshed the whole field of view, and a threshold or a smoothing
  // asked for was ignored without a word. A sphere of radius 7 mm at about 1000 in a background of
  // about 200, each voxel off by up to 50 (1 mm voxels, 24^3).
  const fs::path folder = freshFolder("e2e-mri-kind");
  const double sphere = 4.0 / 3.0 * 3.14159265358979 * 7.0 * 7.0 * 7.0;
  const auto inSphere = [](int i, int j, int k)
  { return (i - 11.5) * (i - 11.5) + (j - 11.5) * (j - 11.5) + (k - 11.5) * (k - 11.5) <= 49.0; };
  const fs::path mri = folder / "mri.mha";
  writeMetaImageOf<std::uint16_t>(mri, { 24, 24, 24 }, { 1.0, 1.0, 1.0 }, [&](int i, int j, int k) -> std::uint16_t
  {
    const unsigned noise = (static_cast<unsigned>(i) * 73856093u ^ static_cast<unsigned>(j) * 19349663u ^
                            static_cast<unsigned>(k) * 83492791u) % 101u;
    return static_cast<std::uint16_t>((inSphere(i, j, k) ? 1000 : 200) + static_cast<int>(noise) - 50);
  });
  const fs::path output = folder / "out.vtp", parameters = folder / "out.params";
  const auto run = [&](const fs::path& input, const std::string& options)
  { return runSliceMesh(options + " --returnparameterfile " + quoted(parameters.string()) + " " + quoted(input.string()) +
                        " " + quoted(output.string())); };
  RunResult r = run(mri, "");
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("input kind Grayscale, chosen from the voxels: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("neighbouring non-zero voxels differ in"), std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(returnParameterMap(parameters).at("volume")), sphere, 0.1 * sphere);

  // Three values only (a label map by its voxels): a threshold asked for makes it grayscale.
  const fs::path plain = folder / "plain.mha";
  writeMetaImageOf<std::uint16_t>(plain, { 24, 24, 24 }, { 1.0, 1.0, 1.0 }, [&](int i, int j, int k) -> std::uint16_t
                                  { return inSphere(i, j, k) ? 1000 : i > 1 && i < 22 ? 200 : 0; });
  r = run(plain, "--thresholdMethod Manual --threshold 600");
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("input kind Grayscale, chosen from the options: --thresholdMethod Manual"), std::string::npos)
    << r.out;
  EXPECT_NEAR(std::stod(returnParameterMap(parameters).at("volume")), sphere, 0.1 * sphere);
  r = run(plain, "--gaussianSigma 0.5");
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("chosen from the options: --gaussianSigma"), std::string::npos) << r.out;
  // Told it is a label map, the grayscale option is said to do nothing, and the labels are meshed.
  r = run(plain, "--inputKind LabelMap --gaussianSigma 0.5");
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.err.find("warning: --gaussianSigma is for a grayscale volume"), std::string::npos) << r.err;
  EXPECT_NEAR(std::stod(returnParameterMap(parameters).at("volume")), 20.0 * 24 * 24, 0.02 * 20.0 * 24 * 24);

  // A label picked beside a grayscale kind or option is refused; on a volume taken as grayscale too.
  r = run(plain, "--label 1000 --gaussianSigma 0.5");
  EXPECT_EQ(r.exitCode, cli::BadArguments) << r.err;
  EXPECT_NE(r.err.find("--label picks a label of a label map, and --gaussianSigma"), std::string::npos) << r.err;
  r = run(plain, "--inputKind Grayscale --label 1000");
  EXPECT_EQ(r.exitCode, cli::BadArguments) << r.err;
  r = run(mri, "--label 1000");
  EXPECT_NE(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.err.find("give --inputKind LabelMap to mesh its voxels of value 1000"), std::string::npos) << r.err;
}

} // namespace
TEST(EndToEnd, ALabelMapsNegativeLabelsAreMeshedByLabelAndByLabels)
{
  // A signed label map given as one: --label -5 meshed label -5, while --labels -5 and one mesh per
  // label refused the whole map for its negative voxels. Boxes of 4 x 4 x 4 voxels (1 mm): -5 and 3.
  const fs::path folder = freshFolder("e2e-negative-labels");
  const fs::path input = folder / "signed.mha";
  writeMetaImageOf<std::int16_t>(input, { 14, 8, 8 }, { 1.0, 1.0, 1.0 }, [](int i, int j, int k) -> std::int16_t
                                 { return j < 2 || j >= 6 || k < 2 || k >= 6 ? 0 : i >= 2 && i < 6 ? -5 : i >= 8 && i < 12 ? 3 : 0; });
  const std::string given = "--inputKind LabelMap ";
  const auto volumeOf = [&](const std::string& options, const std::string& name)
  {
    const fs::path parameters = folder / (name + ".params");
    const RunResult r = runSliceMesh(given + options + " --returnparameterfile " + quoted(parameters.string()) + " " +
                                     quoted(input.string()) + " " + quoted((folder / (name + ".vtp")).string()));
    EXPECT_EQ(r.exitCode, cli::Success) << options << ": " << r.err;
    return r.exitCode == cli::Success ? std::stod(returnParameterMap(parameters).at("volume")) : 0.0;
  };
  const double byLabel = volumeOf("--label -5", "label");
  EXPECT_NEAR(byLabel, 64.0, 0.1 * 64.0);
  EXPECT_NEAR(volumeOf("--labels -5 --outputDirectory " + quoted((folder / "one").string()), "labels"), byLabel, 0.01 * byLabel);
  EXPECT_TRUE(fs::exists(folder / "one" / "-005_Label_-5.vtp"));
  EXPECT_NEAR(volumeOf("--splitLabels --outputDirectory " + quoted((folder / "all").string()), "all"), 2.0 * byLabel,
              0.02 * byLabel);
  EXPECT_TRUE(fs::exists(folder / "all" / "-005_Label_-5.vtp"));
  EXPECT_TRUE(fs::exists(folder / "all" / "003_Label_3.vtp"));

  // Not given as a label map, a volume with negative values is none (a CT's): one mesh per label
  // refuses it and says how to mesh them.
  const RunResult automatic = runSliceMesh("--splitLabels " + quoted(input.string()) + " " + quoted((folder / "auto.vtp").string()));
  EXPECT_EQ(automatic.exitCode, cli::EmptySegmentation) << automatic.err;
  EXPECT_NE(automatic.err.find("holds -5: a negative value, which is a label only in a volume given with --inputKind LabelMap"),
            std::string::npos)
    << automatic.err;
}

TEST(EndToEnd, AShearedGridsReportSaysWhatItsFileHolds)
{
  // NRRD can state axes that are not at right angles (here the second leans 0.3 mm per mm towards
  // the first, and slices are 2 mm): a voxel is then 2 mm^3, not the product of the axes' lengths
  // (2.09). The mesh lands in physical space through the sheared axes; its report's volume, area and
  // angles are measured there too, not in the grid's own frame, and so is the voxels' volume it is
  // held to (a mesh exact on a gantry-tilted grid was said to fall 7-9% short of it).
  const fs::path folder = freshFolder("sheared");
  const fs::path input = folder / "sheared.nrrd", output = folder / "box.vtp", report = folder / "box.json";
  {
    std::ofstream out(input, std::ios::binary);
    out << "NRRD0004\ntype: uint8\ndimension: 3\nspace: left-posterior-superior\nsizes: 16 14 12\n"
        << "space directions: (1,0,0) (0.3,1,0) (0,0,2)\nkinds: domain domain domain\nendian: little\n"
        << "encoding: raw\nspace origin: (3,-4,5)\n\n";
    for (int k = 0; k < 12; ++k)
      for (int j = 0; j < 14; ++j)
        for (int i = 0; i < 16; ++i)
          out.put(static_cast<char>(i >= 3 && i < 13 && j >= 3 && j < 11 && k >= 3 && k < 9 ? 1 : 0));
  }
  const RunResult r = runSliceMesh("--report " + quoted(report.string()) + " " + quoted(input.string()) + " " +
                                   quoted(output.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const TriangleMesh mesh = readMesh(output.string()).mesh;
  const MeshValidation file = validateMesh(mesh);
  EXPECT_TRUE(file.valid()) << file.summary();
  const double voxels = 10.0 * 8.0 * 6.0 * 2.0;
  EXPECT_NEAR(file.volume, voxels, 0.01 * voxels);
  const std::string json = fileText(report);
  EXPECT_NEAR(jsonNumberAfter(json, "volumeMm3"), file.volume, 1e-6 * voxels);
  EXPECT_NEAR(jsonNumberAfter(json, "areaMm2"), file.area, 1e-6 * file.area);
  // The voxels' volume it is measured against, too: 2 mm^3 a voxel, not the axes' product 2.09.
  EXPECT_NEAR(jsonNumberAfter(json, "targetVolumeMm3"), voxels, 1e-6 * voxels);
}

TEST(EndToEnd, TheSameVoxelsOnSpacingsAPartIn10To8ApartGiveTheSameMesh)
{
  // One header written in double precision, the other as single precision rounds it (a NIfTI copy,
  // or a direction matrix rounded, whose columns' lengths are the spacing): the meshes were a few
  // triangles apart. An ellipsoid with a tunnel, on 0.9 x 0.9 x 2.5 mm voxels.
  const fs::path folder = freshFolder("spacing-rounding");
  auto write = [&](const fs::path& path, const std::array<double, 3>& spacing)
  {
    std::ofstream out(path, std::ios::binary);
    out.precision(17);
    out << "NRRD0004\ntype: uint8\ndimension: 3\nspace: left-posterior-superior\nsizes: 48 40 24\n"
        << "space directions: (" << spacing[0] << ",0,0) (0," << spacing[1] << ",0) (0,0," << spacing[2] << ")\n"
        << "endian: little\nencoding: raw\nspace origin: (0,0,0)\n\n";
    for (int k = 0; k < 24; ++k)
      for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 48; ++i)
        {
          const double x = (i - 23.3) * 0.9, y = (j - 19.6) * 0.9, z = (k - 11.4) * 2.5;
          const double ring = std::hypot(x, y - 3.0) - 9.0;
          const bool inside = (x / 18) * (x / 18) + (y / 14) * (y / 14) + (z / 22) * (z / 22) < 1.0 &&
                              ring * ring + (z - 4.0) * (z - 4.0) >= 16.0;
          out.put(static_cast<char>(inside ? 1 : 0));
        }
  };
  write(folder / "double.nrrd", { 0.9, 0.9, 2.5 });
  write(folder / "rounded.nrrd", { 0.9 * (1 + 3e-8), 0.9 * (1 - 2e-8), 2.5 * (1 + 3e-8) });
  for (const char* name : { "double", "rounded" })
  {
    const RunResult r = runSliceMesh(quoted((folder / (std::string(name) + ".nrrd")).string()) + " " +
                                     quoted((folder / (std::string(name) + ".vtp")).string()));
    ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  }
  EXPECT_EQ(fileText(folder / "double.vtp"), fileText(folder / "rounded.vtp"));
  EXPECT_TRUE(validateMesh(readMesh((folder / "double.vtp").string()).mesh).valid());
}

TEST(EndToEnd, ANameTwoLabelsShareMeshesBothAndSaysSo)
{
  // A colour table that gives two labels one name: asked for by the name, both are meshed, and the
  // run says so (it did not: the user asking for "Heart" got two structures without a word). And
  // one that lists a value twice.
  const fs::path folder = freshFolder("shared-name");
  const fs::path input = folder / "two.mha", table = folder / "names.txt";
  writeMetaImage(input, { 12, 10, 8 }, { 1.0, 1.0, 1.0 },
                 [](int i, int j, int k) -> unsigned char
                 {
                   if (j < 2 || j > 7 || k < 2 || k > 5)
                     return 0;
                   return i >= 2 && i < 5 ? 1 : i >= 7 && i < 10 ? 2 : 0;
                 });
  std::ofstream(table) << "1 Heart\n2 Heart\n";
  const RunResult r = runSliceMesh("--labels heart --colorTable " + quoted(table.string()) + " " + quoted(input.string()) +
                                   " " + quoted((folder / "heart.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.out.find("2 labels are named 'Heart', and each is meshed: 1 2"), std::string::npos) << r.out;
  EXPECT_EQ(validateMesh(readMesh((folder / "heart.vtp").string()).mesh).components, 2u);

  // A table that lists a value twice: the last line names it, and the run says so.
  const fs::path repeated = folder / "repeated.txt";
  std::ofstream(repeated) << "1 Heart\n2 Lung\n2 LungDup\n";
  const RunResult twice = runSliceMesh("--labels 2 --colorTable " + quoted(repeated.string()) + " --outputDirectory " +
                                       quoted((folder / "lung").string()) + " " + quoted(input.string()) + " " +
                                       quoted((folder / "lung.vtp").string()));
  ASSERT_EQ(twice.exitCode, cli::Success) << twice.err;
  EXPECT_NE(twice.out.find("lists 1 value(s) more than once; each takes its last line (value 2: 'LungDup')"),
            std::string::npos)
    << twice.out;
  EXPECT_TRUE(fs::exists(folder / "lung" / "002_LungDup.vtp"));
}

TEST(EndToEnd, ALabelMapsNaNVoxelsAreBackgroundAndSaidSoWhenNothingElseIsLeft)
{
  // NaN is no label: in a float volume given as a label map it is background (a map masked with NaN
  // outside its structures meshes them), and one of nothing but 0 and NaN does not say "every voxel is 0".
  const fs::path folder = freshFolder("e2e-nan-labels");
  const auto inBall = [](int i, int j, int k) { return (i - 9.5) * (i - 9.5) + (j - 9.5) * (j - 9.5) + (k - 7.5) * (k - 7.5) < 25.0; };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  writeMetaImageOf<float>(folder / "nan-ball.mha", { 20, 20, 16 }, { 1.0, 1.0, 1.0 },
                          [&](int i, int j, int k) { return inBall(i, j, k) ? nan : 0.0f; });
  std::array<int, 3> first{ -1, -1, -1 }; // in the file's order: i fastest
  for (int k = 15; k >= 0; --k)
    for (int j = 19; j >= 0; --j)
      for (int i = 19; i >= 0; --i)
        if (inBall(i, j, k))
          first = { i, j, k };
  const RunResult r = runSliceMesh("--inputKind LabelMap " + quoted((folder / "nan-ball.mha").string()) + " " +
                                   quoted((folder / "nan.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::EmptySegmentation) << r.err;
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("every voxel is 0 or NaN, taken as background"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the first at index (" + std::to_string(first[0]) + ", " + std::to_string(first[1]) + ", " +
                       std::to_string(first[2]) + ")"),
            std::string::npos)
    << r.err;
  EXPECT_FALSE(fs::exists(folder / "nan.vtp"));

  writeMetaImageOf<float>(folder / "nan-outside.mha", { 20, 20, 16 }, { 1.0, 1.0, 1.0 },
                          [&](int i, int j, int k) { return inBall(i, j, k) ? 1.0f : i < 3 ? nan : 0.0f; });
  const RunResult masked = runSliceMesh("--inputKind LabelMap " + quoted((folder / "nan-outside.mha").string()) + " " +
                                        quoted((folder / "ball.vtp").string()));
  EXPECT_EQ(masked.exitCode, cli::Success) << masked.err;
}

} // namespace slicemesh::testing

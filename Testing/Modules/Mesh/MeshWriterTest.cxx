// writeMesh: every format round-trips through VTK's readers, carries its SPACE tag, and a failed
// write leaves an existing file untouched.
#include "FileReplacement.h"
#include "MeshWriter.h"
#include "Core/Lowercase.h"
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace slicemesh
{
namespace
{

/** A fresh, empty folder per test under the build tree. */
fs::path freshFolder(const std::string& name)
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string fileText(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/** What a reader gives back: the polydata and the coordinate-system text Slicer would look at. */
struct ReadBack
{
  vtkSmartPointer<vtkPolyData> polyData;
  std::string spaceText;
};

std::string fieldDataSpace(vtkPolyData* polyData)
{
  auto* space = vtkStringArray::SafeDownCast(polyData->GetFieldData()->GetAbstractArray("SPACE"));
  return space && space->GetNumberOfValues() == 1 ? "SPACE=" + space->GetValue(0) : std::string();
}

ReadBack readBack(const fs::path& path)
{
  const std::string extension = lowercase(path.extension().string());
  ReadBack result;
  if (extension == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    result.polyData = reader->GetOutput();
    result.spaceText = fieldDataSpace(result.polyData);
  }
  else if (extension == ".vtk")
  {
    vtkNew<vtkPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    result.polyData = reader->GetOutput();
    result.spaceText = reader->GetHeader() ? reader->GetHeader() : "";
  }
  else if (extension == ".stl")
  {
    vtkNew<vtkSTLReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    result.polyData = reader->GetOutput();
    result.spaceText = reader->GetHeader() ? reader->GetHeader() : "";
  }
  else if (extension == ".ply")
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    result.polyData = reader->GetOutput();
    vtkStringArray* comments = reader->GetComments();
    for (vtkIdType i = 0; comments && i < comments->GetNumberOfValues(); ++i)
    {
      result.spaceText += comments->GetValue(i) + "\n";
    }
  }
  else if (extension == ".obj")
  {
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    result.polyData = reader->GetOutput();
    result.spaceText = reader->GetComment() ? reader->GetComment() : "";
  }
  return result;
}

/** Signed volume of what a reader returned (triangles only), to check the winding survived. */
double signedVolumeOf(vtkPolyData* polyData)
{
  TriangleMesh mesh;
  for (vtkIdType i = 0; i < polyData->GetNumberOfPoints(); ++i)
  {
    double p[3];
    polyData->GetPoint(i, p);
    mesh.points.push_back({ p[0], p[1], p[2] });
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = polyData->GetPolys();
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
  {
    if (ids->GetNumberOfIds() == 3)
    {
      mesh.triangles.push_back({ static_cast<std::int32_t>(ids->GetId(0)), static_cast<std::int32_t>(ids->GetId(1)),
                                 static_cast<std::int32_t>(ids->GetId(2)) });
    }
  }
  return testing::signedVolume(mesh);
}

class MeshWriterFormat : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MeshWriterFormat, RoundTripsWithCountsWindingAndSpaceTag)
{
  const std::string extension = GetParam();
  const fs::path folder = freshFolder("roundtrip" + extension);
  const TriangleMesh mesh = testing::box(2, 3, 4);
  for (CoordinateSystem system : { CoordinateSystem::LPS, CoordinateSystem::RAS })
  {
    const std::string space = system == CoordinateSystem::LPS ? "LPS" : "RAS";
    const fs::path path = folder / ("box-" + space + extension);
    writeMesh(mesh, system, path.string());

    const ReadBack back = readBack(path);
    ASSERT_TRUE(back.polyData) << path;
    EXPECT_EQ(back.polyData->GetNumberOfPoints(), 8) << path;
    EXPECT_EQ(back.polyData->GetNumberOfPolys(), 12) << path;
    EXPECT_NEAR(signedVolumeOf(back.polyData), 24.0, 1e-4) << path;
    EXPECT_NE(back.spaceText.find("SPACE=" + space), std::string::npos) << path << ": '" << back.spaceText << "'";
  }
  // Only the two finished files: no temporary left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 2);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, MeshWriterFormat, ::testing::Values(".vtp", ".vtk", ".stl", ".ply", ".obj"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(MeshWriter, LegacyVTKCarriesSpaceInFieldDataToo)
{
  const fs::path path = freshFolder("legacy") / "box.vtk";
  writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string());
  EXPECT_EQ(fieldDataSpace(readBack(path).polyData), "SPACE=LPS");
}

/** The unit cube's surface with each triangle split into four, `rounds` times over, its vertices
 *  moved by an irregular amount (coordinates that use their low bits, as a smoothed mesh's do). */
TriangleMesh perturbedCube(int rounds)
{
  TriangleMesh mesh = testing::box(1, 1, 1);
  for (int round = 0; round < rounds; ++round)
  {
    TriangleMesh finer;
    finer.points = mesh.points;
    std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> middle;
    auto midpoint = [&](std::int32_t a, std::int32_t b)
    {
      const auto key = std::minmax(a, b);
      const auto found = middle.find(key);
      if (found != middle.end())
        return found->second;
      const Point3& p = finer.points[static_cast<std::size_t>(a)];
      const Point3& q = finer.points[static_cast<std::size_t>(b)];
      finer.points.push_back({ (p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2 });
      return middle[key] = static_cast<std::int32_t>(finer.points.size() - 1);
    };
    for (const Triangle& t : mesh.triangles)
    {
      const std::int32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.triangles.push_back({ t[0], ab, ca });
      finer.triangles.push_back({ ab, t[1], bc });
      finer.triangles.push_back({ ca, bc, t[2] });
      finer.triangles.push_back({ ab, bc, ca });
    }
    mesh = finer;
  }
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    const double wobble = 1e-3 * std::sin(1.7 * static_cast<double>(v));
    mesh.points[v] = { mesh.points[v].x + wobble, mesh.points[v].y - wobble, mesh.points[v].z + 0.5 * wobble };
  }
  return mesh;
}

/** Every coordinate read back bit for bit, every triangle's corners as they were. */
void expectExactly(const TriangleMesh& mesh, vtkPolyData* back)
{
  ASSERT_EQ(back->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.points.size()));
  ASSERT_EQ(back->GetNumberOfPolys(), static_cast<vtkIdType>(mesh.triangles.size()));
  std::size_t differentPoints = 0, differentTriangles = 0;
  for (vtkIdType v = 0; v < back->GetNumberOfPoints(); ++v)
  {
    double p[3];
    back->GetPoint(v, p);
    const Point3& q = mesh.points[static_cast<std::size_t>(v)];
    differentPoints += p[0] != q.x || p[1] != q.y || p[2] != q.z;
  }
  vtkCellArray* polys = back->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  for (std::size_t t = 0; polys->GetNextCell(ids); ++t)
    for (int corner = 0; corner < 3; ++corner)
      differentTriangles += ids->GetId(corner) != mesh.triangles[t][static_cast<std::size_t>(corner)];
  EXPECT_EQ(differentPoints, 0u);
  EXPECT_EQ(differentTriangles, 0u);
}

TEST(MeshWriter, VTPIsCompressedAsZLibBlocksThatReadBackExactly)
{
  const fs::path path = freshFolder("compressed") / "cube.vtp";
  const TriangleMesh mesh = perturbedCube(6); // 24,578 points, 49,152 triangles: several zlib blocks per array
  writeMesh(mesh, CoordinateSystem::LPS, path.string());
  // Declared as VTK's zlib compressor: every VTK reader (3D Slicer's, ParaView's) inflates its blocks.
  EXPECT_NE(fileText(path).find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  const std::size_t rawBytes = mesh.points.size() * 3 * sizeof(double) + mesh.triangles.size() * 4 * sizeof(std::int32_t);
  EXPECT_LT(fs::file_size(path), rawBytes * 9 / 10) << "the arrays were not compressed";

  const ReadBack back = readBack(path);
  ASSERT_TRUE(back.polyData);
  // LPS is the mesh's own frame: every coordinate comes back bit for bit, every triangle as it was.
  expectExactly(mesh, back.polyData);
}

TEST(MeshWriter, VTPStoresBlocksThatBarelyCompressAndStillReadsThemBackExactly)
{
  // Coordinates with random low bits (as a smoothed surface's are) barely compress: their blocks are
  // stored as they are, still valid zlib streams; the connectivity is compressed as before.
  const fs::path path = freshFolder("stored") / "noise.vtp";
  TriangleMesh mesh;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-250.0, 250.0);
  for (int v = 0; v < 40000; ++v)
    mesh.points.push_back({ coordinate(random), coordinate(random), coordinate(random) });
  for (std::int32_t t = 0; t + 2 < 40000; ++t)
    mesh.triangles.push_back({ t, t + 1, t + 2 });
  writeMesh(mesh, CoordinateSystem::LPS, path.string());
  const std::size_t pointBytes = mesh.points.size() * 3 * sizeof(double);
  const std::size_t connectivityBytes = mesh.triangles.size() * 4 * sizeof(std::int32_t);
  // Stored blocks add a few bytes each (under 0.1%); the connectivity shrinks to well under half.
  EXPECT_LT(fs::file_size(path), pointBytes * 1001 / 1000 + connectivityBytes / 2);

  const ReadBack back = readBack(path);
  ASSERT_TRUE(back.polyData);
  expectExactly(mesh, back.polyData);
}

TEST(MeshWriter, ExtensionIsCaseInsensitive)
{
  // Every format in upper case, each read back whole, and nothing else left in the folder: VTK's PLY
  // writer appended ".ply" to a temporary named ".PLY", so the write "failed" and left that file.
  const fs::path folder = freshFolder("uppercase");
  for (const std::string extension : { ".VTP", ".VTK", ".STL", ".PLY", ".OBJ", ".Ply" })
  {
    const fs::path path = folder / ("box" + extension);
    writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string());
    EXPECT_EQ(readBack(path).polyData->GetNumberOfPolys(), 12) << extension;
  }
  std::size_t files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
  {
    ++files;
    EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 6u);
}

TEST(MeshWriter, ANameOfUpTo255BytesIsWrittenALongerOneRefused)
{
  // The temporary ".<stem>.partial-<pid>.vtp" of a name of 241 to 255 bytes went past the file
  // system's 255 and the write failed after the meshing; a longer name is refused up front.
  const fs::path folder = freshFolder("long-names");
  const fs::path longest = folder / (std::string(251, 'c') + ".vtp");
  writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, longest.string());
  EXPECT_EQ(readBack(longest).polyData->GetNumberOfPolys(), 12);
  const fs::path tooLong = folder / (std::string(252, 'c') + ".vtp");
  try
  {
    writablePlace(tooLong.string(), "mesh");
    ADD_FAILURE() << "a name of 256 bytes";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("its name is 256 bytes long; the file system allows 255"), std::string::npos)
      << e.what();
  }
}

TEST(MeshWriter, UnknownExtensionIsAOneLineError)
{
  const fs::path path = freshFolder("unknown") / "box.xyz";
  try
  {
    writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string());
    FAIL() << "expected slicemesh::Error";
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find(".xyz"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(MeshWriter, MissingFolderIsAnError)
{
  const fs::path path = freshFolder("missing") / "no-such-folder" / "box.vtp";
  EXPECT_THROW(writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string()), Error);
  EXPECT_FALSE(fs::exists(path.parent_path()));
}

TEST(MeshWriter, ReplacesAnExistingFileOnSuccess)
{
  const fs::path path = freshFolder("replace") / "box.vtp";
  std::ofstream(path) << "old contents";
  writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string());
  EXPECT_EQ(readBack(path).polyData->GetNumberOfPolys(), 12);
}

TEST(MeshWriter, FailedWriteLeavesExistingFileUntouched)
{
  const fs::path folder = freshFolder("atomic");
  for (const std::string extension : { ".vtp", ".vtk", ".stl", ".ply", ".obj" })
  {
    const fs::path path = folder / ("box" + extension);
    std::ofstream(path) << "precious";
    // Block the writer's temporary name (same folder, ".<stem>.partial-<pid><ext>") with a folder, so
    // the format writer itself fails; permissions would not stop root.
    const fs::path blocker = folder / (".box.partial-" + std::to_string(::getpid()) + extension);
    fs::create_directory(blocker);
    fs::create_directory(blocker / "keep-non-empty");
    try
    {
      writeMesh(testing::box(1, 1, 1), CoordinateSystem::LPS, path.string());
      ADD_FAILURE() << extension << ": no error";
    }
    catch (const Error& e)
    {
      // The message names the output, never the writer's object address or the temporary name.
      const std::string message = e.what();
      EXPECT_NE(message.find(path.string()), std::string::npos) << message;
      EXPECT_EQ(message.find("0x"), std::string::npos) << message;
      EXPECT_EQ(message.find(".partial-"), std::string::npos) << message;
    }
    EXPECT_EQ(fileText(path), "precious") << extension;
    fs::remove_all(blocker);
  }
}

TEST(MeshWriter, PLYWithFaceColoursPassesItsSizeCheck)
{
  // The written .ply is checked against the length its header declares, colours included.
  const fs::path path = freshFolder("ply-colours") / "box.ply";
  const TriangleMesh mesh = testing::box(1, 1, 1);
  MeshAttributes attributes;
  attributes.cellColors.assign(mesh.triangles.size(), { 250, 120, 0 });
  writeMesh(mesh, CoordinateSystem::LPS, path.string(), attributes);
  EXPECT_NE(fileText(path).find("property uchar red"), std::string::npos);
  EXPECT_EQ(readBack(path).polyData->GetNumberOfPolys(), 12);
}

/** Writes the mesh with files limited to `bytes` and SIGXFSZ ignored, so that a write past the limit
 *  fails as on a full disk, then exits: 0 if writeMesh returned, 3 with its error on stderr if it
 *  threw (for a death test's child, so the limit never reaches the tests' own process). */
[[noreturn]] void writeUnderFileSizeLimit(const TriangleMesh& mesh, const fs::path& path, rlim_t bytes)
{
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit{};
  ::getrlimit(RLIMIT_FSIZE, &limit);
  limit.rlim_cur = bytes;
  ::setrlimit(RLIMIT_FSIZE, &limit);
  try
  {
    writeMesh(mesh, CoordinateSystem::LPS, path.string());
  }
  catch (const Error& e)
  {
    std::cerr << e.what() << std::endl;
    std::exit(3);
  }
  std::exit(0);
}

TEST(MeshWriter, WriteCutShortByAFullDiskFailsAndLeavesExistingFileUntouched)
{
  // vtkPLYWriter reported success for a cut file, which then replaced the existing one; and
  // vtkXMLPolyDataWriter's only message was its pipeline's "FORWARD_DIRECTION: 0".
  const TriangleMesh mesh = perturbedCube(3); // some 15 kB and more in every format
  for (const std::string extension : { ".vtp", ".vtk", ".stl", ".ply", ".obj" })
  {
    const fs::path folder = freshFolder("full-disk" + extension);
    const fs::path path = folder / ("cube" + extension);
    std::ofstream(path, std::ios::binary) << "precious";
    EXPECT_EXIT(writeUnderFileSizeLimit(mesh, path, 4096), ::testing::ExitedWithCode(3),
                "^cannot write mesh '[^']*': (writing the file failed \\(disk full\\?\\)|Ran out of disk space)")
      << extension;
    EXPECT_TRUE(fileText(path) == "precious") << extension << ": the existing file replaced"; // no binary dump
    std::vector<fs::path> left;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
      left.push_back(entry.path().filename());
    EXPECT_EQ(left, std::vector<fs::path>{ path.filename() }) << extension << ": a temporary file left";
  }
}

} // namespace
} // namespace slicemesh

// The --snapshot picture: rendered off screen, coloured by triangle quality, not blank. VTK 9.1 on
// Debian renders through X: without a display the test starts its own Xvfb (package xvfb), and
// skips, saying why, only when neither can be had.
#include "MeshSnapshot.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkDataArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

using namespace slicemesh;
namespace fs = std::filesystem;

namespace
{

/** An Xvfb server of our own for the test program's lifetime, when there is no display. */
class VirtualDisplay : public ::testing::Environment
{
public:
  void SetUp() override
  {
    if (snapshotAvailable())
      return;
    int fds[2];
    if (::pipe(fds) != 0)
      return;
    m_Server = ::fork();
    if (m_Server == 0)
    {
      ::close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      // -noreset: an X server resets when its last client leaves and refuses connections meanwhile.
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp", "-noreset",
               static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    if (m_Server < 0)
      return;
    // Xvfb writes the display number it chose once it accepts connections.
    std::string number;
    char c;
    while (::read(fds[0], &c, 1) == 1 && c != '\n')
      number += c;
    ::close(fds[0]);
    if (number.empty())
      return;
    ::setenv("DISPLAY", (":" + number).c_str(), 1);
    // The server may take a moment more to accept connections.
    for (int attempt = 0; attempt < 50 && !snapshotAvailable(); ++attempt)
      ::usleep(100000);
  }
  void TearDown() override
  {
    if (m_Server > 0)
    {
      ::kill(m_Server, SIGTERM);
      ::waitpid(m_Server, nullptr, 0);
    }
  }

private:
  pid_t m_Server = -1;
};

const ::testing::Environment* const virtualDisplay = ::testing::AddGlobalTestEnvironment(new VirtualDisplay);

/** A UV sphere of radius 10 mm centred at (x, 0, 0), appended to mesh: few sectors give well
 *  shaped triangles, many sectors thin ones. */
void appendUvSphere(TriangleMesh& mesh, int rings, int sectors, double x)
{
  const int first = static_cast<int>(mesh.points.size());
  mesh.points.push_back({ x, 0, 10 });
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s)
    {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * s / sectors;
      mesh.points.push_back({ x + 10 * std::sin(theta) * std::cos(phi), 10 * std::sin(theta) * std::sin(phi),
                              10 * std::cos(theta) });
    }
  mesh.points.push_back({ x, 0, -10 });
  const int north = first;
  const int south = static_cast<int>(mesh.points.size()) - 1;
  auto at = [&](int r, int s) { return first + 1 + (r - 1) * sectors + (s % sectors); };
  for (int s = 0; s < sectors; ++s)
  {
    mesh.triangles.push_back({ north, at(1, s), at(1, s + 1) });
    mesh.triangles.push_back({ south, at(rings - 1, s + 1), at(rings - 1, s) });
    for (int r = 1; r < rings - 1; ++r)
    {
      mesh.triangles.push_back({ at(r, s), at(r + 1, s), at(r + 1, s + 1) });
      mesh.triangles.push_back({ at(r, s), at(r + 1, s + 1), at(r, s + 1) });
    }
  }
}

TriangleMesh uvSphere(int rings, int sectors)
{
  TriangleMesh mesh;
  appendUvSphere(mesh, rings, sectors, 0.0);
  return mesh;
}

/** Where a test's picture goes (output/snapshot/<name>), with no file of an earlier run there. */
fs::path freshPicturePath(const std::string& name)
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "snapshot";
  fs::create_directories(folder);
  const fs::path png = folder / name;
  fs::remove(png);
  return png;
}

SnapshotOptions smallPicture()
{
  SnapshotOptions options;
  options.width = 320;
  options.height = 240;
  return options;
}

} // namespace

TEST(MeshSnapshot, RendersANonBlankPictureColouredByQuality)
{
  std::string reason;
  if (!snapshotAvailable(&reason))
    GTEST_SKIP() << "no X display and no Xvfb could be started: " << reason;
  const fs::path png = freshPicturePath("sphere.png");
  const SnapshotOptions options = smallPicture();
  // One sphere of good triangles, one of slivers (6 rings, 120 sectors: angles of a few degrees).
  TriangleMesh mesh = uvSphere(16, 24);
  appendUvSphere(mesh, 6, 120, 25.0);
  writeSnapshot(mesh, png.string(), options);
  ASSERT_TRUE(fs::exists(png));

  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 320);
  EXPECT_EQ(dims[1], 240);
  vtkDataArray* pixels = image->GetPointData()->GetScalars();
  ASSERT_NE(pixels, nullptr);
  ASSERT_GE(pixels->GetNumberOfComponents(), 3);
  // Not blank: the pixels vary, many are not the white background, and both the red of the
  // poles' slivers and the green of the good triangles appear.
  double sum = 0.0, sumSquares = 0.0;
  std::size_t notWhite = 0, reddish = 0, greenish = 0;
  const vtkIdType n = pixels->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double r = pixels->GetComponent(i, 0), g = pixels->GetComponent(i, 1), b = pixels->GetComponent(i, 2);
    const double grey = (r + g + b) / 3.0;
    sum += grey;
    sumSquares += grey * grey;
    notWhite += grey < 250.0;
    reddish += r > g + 60 && r > b + 60;
    greenish += g > r + 60 && g > b + 60;
  }
  const double mean = sum / n, variance = sumSquares / n - mean * mean;
  std::printf("snapshot: mean %.1f, variance %.1f, %zu of %lld pixels drawn, %zu red, %zu green\n", mean, variance,
              notWhite, static_cast<long long>(n), reddish, greenish);
  EXPECT_GT(variance, 100.0);
  EXPECT_GT(notWhite, static_cast<std::size_t>(n / 10));
  EXPECT_GT(greenish, 100u);
  EXPECT_GT(reddish, 100u);
}

TEST(MeshSnapshot, FailsWithAOneLineErrorAndNoFile)
{
  std::string reason;
  if (!snapshotAvailable(&reason))
    GTEST_SKIP() << reason;
  EXPECT_THROW(writeSnapshot(uvSphere(8, 8), "/nonexistent-folder/x.png"), Error);
  EXPECT_THROW(writeSnapshot(TriangleMesh{}, (fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "empty.png").string()), Error);
  EXPECT_FALSE(fs::exists(fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "empty.png"));
}

TEST(MeshSnapshot, SeveralMeshesEachInItsColour)
{
  std::string reason;
  if (!snapshotAvailable(&reason))
    GTEST_SKIP() << "no X display and no Xvfb could be started: " << reason;
  const fs::path png = freshPicturePath("two-labels.png");
  const SnapshotOptions options = smallPicture();
  // Two spheres side by side, as two labels merged: the left one blue, the right one red.
  TriangleMesh meshes = uvSphere(16, 24);
  const std::size_t first = meshes.triangles.size();
  appendUvSphere(meshes, 16, 24, 25.0);
  std::vector<std::array<unsigned char, 3>> colours(meshes.triangles.size(), { 200, 30, 30 });
  std::fill(colours.begin(), colours.begin() + static_cast<std::ptrdiff_t>(first), std::array<unsigned char, 3>{ 30, 30, 200 });
  EXPECT_THROW(writeSnapshot(meshes, std::vector<std::array<unsigned char, 3>>(first), png.string(), options), Error);
  EXPECT_FALSE(fs::exists(png));
  writeSnapshot(meshes, colours, png.string(), options);
  ASSERT_TRUE(fs::exists(png));

  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.string().c_str());
  reader->Update();
  vtkDataArray* pixels = reader->GetOutput()->GetPointData()->GetScalars();
  ASSERT_NE(pixels, nullptr);
  // Both colours are drawn, each over a good part of the picture, and nothing is green (no quality
  // colouring). Shading darkens a colour but keeps its dominant channel.
  std::size_t reddish = 0, bluish = 0, greenish = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const double r = pixels->GetComponent(i, 0), g = pixels->GetComponent(i, 1), b = pixels->GetComponent(i, 2);
    reddish += r > g + 40 && r > b + 40;
    bluish += b > r + 40 && b > g + 40;
    greenish += g > r + 40 && g > b + 40;
  }
  std::printf("two labels: %zu red, %zu blue, %zu green pixels\n", reddish, bluish, greenish);
  EXPECT_GT(reddish, 2000u);
  EXPECT_GT(bluish, 2000u);
  EXPECT_EQ(greenish, 0u);
}

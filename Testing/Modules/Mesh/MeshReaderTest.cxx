// readMesh gives back what writeMesh wrote: geometry, per-triangle labels and colours, structures.
#include "MeshReader.h"
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace slicemesh;

namespace
{

fs::path outputFolder()
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "mesh-reader";
  fs::create_directories(folder);
  return folder;
}

} // namespace

TEST(MeshReader, ReadsBackWhatTheWriterWrote)
{
  // Twelve triangles: the first six of structure 3, the rest of structure 7.
  const TriangleMesh mesh = slicemesh::testing::box(2.0, 3.0, 4.0);
  MeshAttributes attributes;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    attributes.cellLabels.push_back(t < 6 ? 3 : 7);
    attributes.cellColors.push_back(t < 6 ? std::array<unsigned char, 3>{ 250, 0, 0 }
                                          : std::array<unsigned char, 3>{ 0, 120, 250 });
  }
  attributes.structures = { { 3, "Heart", { 250, 0, 0, 255 } }, { 7, "Lung_L", { 0, 120, 250, 255 } } };
  for (const char* extension : { ".vtp", ".vtk" })
  {
    const fs::path path = outputFolder() / (std::string("labelled") + extension);
    writeMesh(mesh, CoordinateSystem::LPS, path.string(), attributes);
    const MeshFile read = readMesh(path.string());
    ASSERT_EQ(read.mesh.points.size(), mesh.points.size()) << extension;
    for (std::size_t n = 0; n < mesh.points.size(); ++n)
    {
      EXPECT_NEAR(read.mesh.points[n].x, mesh.points[n].x, 1e-6);
      EXPECT_NEAR(read.mesh.points[n].y, mesh.points[n].y, 1e-6);
      EXPECT_NEAR(read.mesh.points[n].z, mesh.points[n].z, 1e-6);
    }
    EXPECT_EQ(read.mesh.triangles, mesh.triangles) << extension;
    EXPECT_EQ(read.attributes.cellLabels, attributes.cellLabels) << extension;
    EXPECT_EQ(read.attributes.cellColors, attributes.cellColors) << extension;
    ASSERT_EQ(read.attributes.structures.size(), 2u) << extension;
    EXPECT_EQ(read.attributes.structures[1].value, 7);
    EXPECT_EQ(read.attributes.structures[1].name, "Lung_L");
    EXPECT_EQ(read.attributes.structures[1].rgba, (std::array<unsigned char, 4>{ 0, 120, 250, 255 }));
  }
}

TEST(MeshReader, AFileThatIsNoMeshIsAnError)
{
  const fs::path path = outputFolder() / "not-a-mesh.vtp";
  std::ofstream(path) << "hello";
  EXPECT_THROW(readMesh(path.string()), Error);
  EXPECT_THROW(readMesh((outputFolder() / "missing.vtk").string()), Error);
  EXPECT_THROW(readMesh((outputFolder() / "mesh.stl").string()), Error);
}

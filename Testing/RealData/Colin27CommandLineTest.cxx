// The executable on the Colin27 T1 MRI (mricron-data's ch2.nii.gz, 181 x 217 x 181, 1 mm, 8-bit), run
// as a new user runs it from the README's grayscale example. A threshold of 100 through this head
// gives thousands of thin, touching, holed pieces with flat caps: the run that used to die inside
// CGAL's isotropic remeshing (a null halfedge in its tangential relaxation).
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "RealDataSupport.h"

#include <gtest/gtest.h>

#include <regex>

namespace slicemesh::testing
{
namespace
{

const std::string t1 = mricronTemplates + "ch2.nii.gz";

TEST(Colin27CommandLine, ThresholdedAt100InRasWithFlatCapsWritesAValidMesh)
{
  const std::filesystem::path folder = freshFolder("Colin27CommandLine");
  const std::filesystem::path mesh = folder / "brain.vtk", results = folder / "results.txt";
  const RunResult run = runSliceMesh("--inputKind Grayscale --thresholdMethod Manual --threshold 100 "
                                     "--coordinateSystem RAS --capPlacement AtSlice --returnparameterfile " +
                                     quoted(results.string()) + " " + quoted(t1) + " " + quoted(mesh.string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err;
  ASSERT_TRUE(std::filesystem::exists(mesh));
  bool closed = false;
  double triangles = 0.0;
  for (const auto& [name, value] : returnParameters(results))
  {
    if (name == "closed")
      closed = value == "true";
    if (name == "triangles")
      triangles = std::stod(value);
  }
  EXPECT_TRUE(closed);
  EXPECT_GT(triangles, 100000.0);
  // The summary says what each piece got, not only the least finished one.
  EXPECT_NE(run.out.find("finish Remeshed"), std::string::npos) << run.out;
  std::cout << run.out.substr(0, 400) << std::endl;
}

TEST(Colin27CommandLine, AThresholdAboveTheImageNamesItsIntensityRange)
{
  const std::filesystem::path folder = freshFolder("Colin27Threshold300");
  const std::filesystem::path mesh = folder / "brain.vtk";
  const RunResult run = runSliceMesh("--inputKind Grayscale --thresholdMethod Manual --threshold 300 " + quoted(t1) +
                                     " " + quoted(mesh.string()));
  EXPECT_EQ(run.exitCode, cli::EmptySegmentation);
  EXPECT_EQ(linesOf(run.err).size(), 1u) << run.err;
  std::smatch range;
  ASSERT_TRUE(std::regex_search(run.err, range, std::regex("intensities run from (-?[0-9.e+-]+) to (-?[0-9.e+-]+)")))
    << run.err;
  EXPECT_LE(std::stod(range[1].str()), std::stod(range[2].str()));
  EXPECT_LT(std::stod(range[2].str()), 300.0); // why nothing was selected
  EXPECT_FALSE(std::filesystem::exists(mesh));
}

} // namespace
} // namespace slicemesh::testing

// What a run loads: GDCM, DCMTK and VTK's rendering are plugins (Modules/Plugins), loaded only by a
// run that reads DICOM or draws a snapshot. Checked on the executable through the dynamic loader's
// own trace of the files it opens (LD_DEBUG=files), and on the loader's message when a plugin is
// missing.
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "PluginLoader.h"
#include "StructureSetWriter.h"
#include "TestContours.h"

#include "Core/SliceMeshTypes.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

/** The run's exit code and the shared libraries the loader opened (its trace on stderr). */
RunResult tracedRun(const std::string& arguments)
{
  return runCommand("LD_DEBUG=files " + quoted(SLICEMESH_EXECUTABLE) + " " + arguments);
}

bool opened(const RunResult& run, const std::string& library)
{
  return run.err.find("file=" + library) != std::string::npos;
}

/** The libraries only plugins bring: GDCM, DCMTK, VTK's OpenGL rendering, OpenGL itself. */
const char* const pluginOnly[] = { "libgdcm", "libdcmdata", "libdcmrt", "libdcmseg", "libvtkRenderingOpenGL2",
                                   "libGL.so", "libX11" };

TEST(Plugins, ALabelMapRunLoadsNoPlugin)
{
  const fs::path folder = freshFolder("PluginsLabelMap");
  writeMetaImage(folder / "ball.mha", { 24, 24, 24 }, { 1.0, 1.0, 1.0 },
                 [](int i, int j, int k) { return (i - 12) * (i - 12) + (j - 12) * (j - 12) + (k - 12) * (k - 12) < 49; });
  const RunResult run = tracedRun(quoted((folder / "ball.mha").string()) + " " + quoted((folder / "ball.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err.substr(run.err.size() > 2000 ? run.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::exists(folder / "ball.vtp"));
  ASSERT_TRUE(opened(run, "libITKCommon")) << "no loader trace on stderr";
  for (const char* library : pluginOnly)
    EXPECT_FALSE(opened(run, library)) << library;
  EXPECT_FALSE(opened(run, std::string(pluginFolderName))) << "a plugin was loaded";
}

TEST(Plugins, AStructureSetRunLoadsTheStructureSetPluginAndDcmtkOnly)
{
  const fs::path folder = freshFolder("PluginsStructureSet");
  PlanarStructure disc;
  disc.number = 1;
  disc.name = "Disc";
  for (int k = 0; k < 6; ++k)
    disc.contours.push_back(circle(0.0, 0.0, 3.0 * k, 15.0));
  writeRTStructureSet((folder / "RS.dcm").string(), { disc });
  const RunResult run = tracedRun(quoted((folder / "RS.dcm").string()) + " " + quoted((folder / "disc.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err.substr(run.err.size() > 2000 ? run.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::exists(folder / "disc.vtp"));
  EXPECT_NE(run.err.find(std::string(pluginFolderName) + "/libSliceMeshStructuresDicom.so"), std::string::npos);
  EXPECT_TRUE(opened(run, "libdcmrt"));
  for (const char* library : { "libgdcm", "libvtkRenderingOpenGL2", "libGL.so" })
    EXPECT_FALSE(opened(run, library)) << library;
}

TEST(Plugins, AMissingPluginIsAnErrorThatSaysWhatNeedsIt)
{
  try
  {
    pluginEntry("libSliceMeshNoSuchPlugin.so", "slicemeshNoSuchFunctions", "Reading a test file");
    FAIL() << "a plugin that does not exist was loaded";
  }
  catch (const Error& error)
  {
    const std::string message = error.what();
    EXPECT_NE(message.find("Reading a test file needs SliceMesh's plugin libSliceMeshNoSuchPlugin.so"), std::string::npos)
      << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Plugins, AnEntryThePluginLacksIsAnError)
{
  EXPECT_THROW(pluginEntry("libSliceMeshStructuresDicom.so", "slicemeshNoSuchFunctions", "Reading a test file"), Error);
}

} // namespace
} // namespace slicemesh::testing

// What a run loads: GDCM, DCMTK and VTK's rendering are plugins (Modules/Plugins), loaded only by a
// run that reads DICOM or draws a snapshot. Checked on the executable through the dynamic loader's
// own trace of the files it opens (LD_DEBUG=files), and on the loader's message when a plugin is
// missing.
#include "CLITestSupport.h"
#include "DicomSeriesWriter.h"
#include "ExitCodes.h"
#include "PluginLoader.h"
#include "StructureSetWriter.h"
#include "TestContours.h"
#include "TestPlugin.h"

#include "Core/SliceMeshTypes.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

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
  EXPECT_EQ(run.err.find(std::string("/") + pluginFolderName + "/"), std::string::npos) << "a plugin was loaded";
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

TEST(Plugins, ASingleDicomImageIsReadThroughTheDicomPluginAndRefusedAsTwoDimensional)
{
  // One slice of a CT series, a disc in it: no reader of the executable's own takes the file, so
  // the DICOM plugin is loaded and its reader (GDCM) reads it. One frame is a 2-D image (GDCM would
  // make it a slice 1 mm thick, a thickness it makes up): refused in one line, as a folder of one
  // slice is.
  const fs::path folder = freshFolder("PluginsSingleDicom");
  auto ct = CTVolume::New();
  ct->SetRegions(CTVolume::SizeType{ { 24, 24, 2 } });
  ct->Allocate(true);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j)
      if ((i - 12) * (i - 12) + (j - 12) * (j - 12) < 36)
        for (int k = 0; k < 2; ++k)
          ct->SetPixel({ { i, j, k } }, 1);
  writeCTSeries(ct, folder / "CT");
  const RunResult run = tracedRun(quoted((folder / "CT" / "slice000.dcm").string()) + " " + quoted((folder / "disc.vtp").string()));
  EXPECT_NE(run.err.find(std::string(pluginFolderName) + "/libSliceMeshImageDicom.so"), std::string::npos);
  EXPECT_TRUE(opened(run, "libgdcm"));
  ASSERT_EQ(run.exitCode, cli::UnreadableInput) << run.err.substr(run.err.size() > 2000 ? run.err.size() - 2000 : 0);
  EXPECT_NE(run.err.find("slice000.dcm: a single DICOM slice (a 2-D image)"), std::string::npos);
  EXPECT_FALSE(fs::exists(folder / "disc.vtp"));
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
  try
  {
    pluginEntry("libSliceMeshStructuresDicom.so", "slicemeshNoSuchFunctions", "Reading a test file");
    FAIL() << "an entry the plugin does not have was found";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("which has no entry slicemeshNoSuchFunctions"), std::string::npos)
      << error.what();
  }
}

TEST(Plugins, ATableOfThisBuildIsCalledAndOneOfAnotherVersionRefused)
{
  ASSERT_NE(dlopen(SLICEMESH_TEST_PLUGIN, RTLD_NOW), nullptr) << dlerror();
  const auto& functions =
    pluginFunctions<TestPluginFunctions>("libSliceMeshTestPlugin.so", "slicemeshTestPluginFunctions", "A test");
  EXPECT_EQ(functions.answer(), 42);
  try
  {
    pluginFunctions<TestPluginFunctions>("libSliceMeshTestPlugin.so", "slicemeshOtherVersionFunctions", "A test");
    FAIL() << "a table of another layout was taken";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("of another SliceMesh version"), std::string::npos) << error.what();
  }
}

} // namespace
} // namespace slicemesh::testing

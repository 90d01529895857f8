// Running the built SliceMesh executable and making small input volumes for it.
#ifndef CLITestSupport_h
#define CLITestSupport_h

#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace slicemesh::testing
{

struct RunResult
{
  int exitCode = -1;
  std::string out; ///< stdout
  std::string err; ///< stderr
};

/** Runs "SliceMesh <arguments>" through the shell; arguments are already quoted as needed. */
RunResult runSliceMesh(const std::string& arguments);

/** Runs any shell command, capturing stdout and stderr. */
RunResult runCommand(const std::string& command);

/** A fresh, empty folder for one test under the build tree. */
std::filesystem::path freshFolder(const std::string& name);

std::string fileText(const std::filesystem::path& path);

/** Single-quotes a path for the shell. */
std::string quoted(const std::string& text);

/** Writes a 3D unsigned-char MetaImage (.mha) whose voxel (i, j, k) is value(i, j, k). */
void writeMetaImage(const std::filesystem::path& path, std::array<int, 3> size, std::array<double, 3> spacing,
                    const std::function<unsigned char(int, int, int)>& value);

/** Lines of text, without their line breaks. */
std::vector<std::string> linesOf(const std::string& text);

/** The numbers inside every <tag>...</tag> of Slicer's progress protocol, in order. */
std::vector<double> tagNumbers(const std::string& output, const std::string& tag);

/** Names of the stages in <filter-start> (or <filter-end>) blocks, in order. */
std::vector<std::string> stageNames(const std::string& output, const std::string& block);

/** "name = value" lines of a return-parameter file, in order. */
std::vector<std::pair<std::string, std::string>> returnParameters(const std::filesystem::path& path);

} // namespace slicemesh::testing

#endif

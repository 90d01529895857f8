#include "CLITestSupport.h"

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace slicemesh::testing
{

std::string quoted(const std::string& text)
{
  std::string result = "'";
  for (char c : text)
  {
    result += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return result + "'";
}

std::string fileText(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

RunResult runCommand(const std::string& command)
{
  static int counter = 0;
  const fs::path errFile =
    fs::temp_directory_path() / ("slicemesh-clitest-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  RunResult result;
  FILE* pipe = ::popen((command + " 2>" + quoted(errFile.string())).c_str(), "r");
  if (!pipe)
  {
    return result;
  }
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
  {
    result.out.append(buffer, n);
  }
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = fileText(errFile);
  fs::remove(errFile);
  return result;
}

RunResult runSliceMesh(const std::string& arguments)
{
  return runCommand(quoted(SLICEMESH_EXECUTABLE) + " " + arguments);
}

fs::path freshFolder(const std::string& name)
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

void writeMetaImage(const fs::path& path, std::array<int, 3> size, std::array<double, 3> spacing,
                    const std::function<unsigned char(int, int, int)>& value)
{
  std::ofstream out(path, std::ios::binary);
  out << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
      << "Offset = 0 0 0\nTransformMatrix = 1 0 0 0 1 0 0 0 1\n"
      << "ElementSpacing = " << spacing[0] << " " << spacing[1] << " " << spacing[2] << "\n"
      << "DimSize = " << size[0] << " " << size[1] << " " << size[2] << "\n"
      << "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n";
  for (int k = 0; k < size[2]; ++k)
  {
    for (int j = 0; j < size[1]; ++j)
    {
      for (int i = 0; i < size[0]; ++i)
      {
        out.put(static_cast<char>(value(i, j, k)));
      }
    }
  }
}

std::vector<std::string> linesOf(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
  {
    lines.push_back(line);
  }
  return lines;
}

std::vector<double> tagNumbers(const std::string& output, const std::string& tag)
{
  std::vector<double> values;
  const std::regex pattern("<" + tag + ">([^<]*)</" + tag + ">");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), pattern); it != std::sregex_iterator(); ++it)
  {
    values.push_back(std::stod((*it)[1]));
  }
  return values;
}

std::vector<std::string> stageNames(const std::string& output, const std::string& block)
{
  std::vector<std::string> names;
  const std::regex pattern("<" + block + ">\\s*<filter-name>([^<]*)</filter-name>");
  for (auto it = std::sregex_iterator(output.begin(), output.end(), pattern); it != std::sregex_iterator(); ++it)
  {
    names.push_back((*it)[1]);
  }
  return names;
}

std::vector<std::pair<std::string, std::string>> returnParameters(const fs::path& path)
{
  std::vector<std::pair<std::string, std::string>> values;
  for (const std::string& line : linesOf(fileText(path)))
  {
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos)
    {
      continue;
    }
    // As ModuleDescription::ReadParameterFile: split at the first '=', trim spaces.
    const auto trim = [](std::string text)
    {
      text.erase(0, text.find_first_not_of(' '));
      text.erase(text.find_last_not_of(' ') + 1);
      return text;
    };
    values.emplace_back(trim(line.substr(0, equals)), trim(line.substr(equals + 1)));
  }
  return values;
}

} // namespace slicemesh::testing

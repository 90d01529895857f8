// SliceMesh.xml: well formed, printed by --xml exactly, installed beside the executable, and
// following the Slicer Execution Model rules (SLICER_CLI.md section 1), checked with xmllint's
// XPath so the check does not rely on the module's own parser.
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "ModuleDescription.h"
#include "ModuleXml.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

std::string xpath(const std::string& expression)
{
  const RunResult r =
    runCommand(quoted(XMLLINT_EXECUTABLE) + " --xpath " + quoted(expression) + " " + quoted(SLICEMESH_XML_SOURCE));
  EXPECT_EQ(r.exitCode, cli::Success) << expression << ": " << r.err;
  std::string value = r.out;
  while (!value.empty() && value.back() == '\n')
  {
    value.pop_back();
  }
  return value;
}

TEST(ModuleXml, SourceIsWellFormed)
{
  const RunResult r = runCommand(quoted(XMLLINT_EXECUTABLE) + " --noout " + quoted(SLICEMESH_XML_SOURCE));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_EQ(r.err, "");
}

TEST(ModuleXml, XmlFlagPrintsExactlyTheSourceAndIsWellFormed)
{
  const RunResult r = runSliceMesh("--xml");
  EXPECT_EQ(r.exitCode, cli::Success);
  EXPECT_EQ(r.out.rfind("<?xml ", 0), 0u) << "Slicer rejects --xml output that does not start with <?xml";
  EXPECT_EQ(r.out, fileText(SLICEMESH_XML_SOURCE));
  EXPECT_EQ(r.err, "");

  const fs::path printed = freshFolder("xml") / "printed.xml";
  std::ofstream(printed) << r.out;
  EXPECT_EQ(runCommand(quoted(XMLLINT_EXECUTABLE) + " --noout " + quoted(printed.string())).exitCode, cli::Success);
}

TEST(ModuleXml, XmlFlagComesBeforeAnyOtherParsing)
{
  const RunResult r = runSliceMesh("--xml --no-such-option");
  EXPECT_EQ(r.exitCode, cli::Success);
  EXPECT_EQ(r.out, fileText(SLICEMESH_XML_SOURCE));
}

TEST(ModuleXml, CopyBesideTheExecutableMatchesTheSource)
{
  const fs::path beside = fs::path(SLICEMESH_EXECUTABLE).parent_path() / "SliceMesh.xml";
  ASSERT_TRUE(fs::exists(beside)) << "Slicer discovers <name>.xml next to the executable";
  EXPECT_EQ(fileText(beside), fileText(SLICEMESH_XML_SOURCE));
}

TEST(ModuleXml, TopLevelElementsComeInTheSchemaOrder)
{
  const std::vector<std::string> expected = { "category", "title", "description", "version", "documentation-url",
                                              "license", "contributor", "acknowledgements" };
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_EQ(xpath("name(/executable/*[" + std::to_string(i + 1) + "])"), expected[i]);
  }
  EXPECT_EQ(xpath("count(/executable/*[position() > 8 and name() != 'parameters'])"), "0");
  EXPECT_EQ(xpath("normalize-space(/executable/category)"), "Surface Models");
  EXPECT_EQ(xpath("normalize-space(/executable/title)"), "SliceMesh");
}

TEST(ModuleXml, FollowsTheSlicerExecutionModelRules)
{
  // One-letter flags.
  EXPECT_EQ(xpath("count(//parameters/*/flag[string-length(translate(normalize-space(.), '-', '')) != 1])"), "0");
  // No flag or longflag together with an index.
  EXPECT_EQ(xpath("count(//parameters/*[index and (flag or longflag)])"), "0");
  // Booleans default to false (present on the command line means true).
  EXPECT_EQ(xpath("count(//parameters/boolean[not(default) or normalize-space(default) != 'false'])"), "0");
  // Every group has a label (CTK requires it) and every parameter a name, label and description.
  EXPECT_EQ(xpath("count(//parameters[not(label)])"), "0");
  EXPECT_EQ(xpath("count(//parameters/*[name() != 'label' and name() != 'description'][not(name) or not(label) or "
                  "not(description)])"),
            "0");
  // The names are identifiers, and the module's parser sees exactly the parameters xmllint sees.
  const cli::ModuleDescription module = cli::parseModuleDescription(cli::moduleXml());
  EXPECT_EQ(xpath("count(//parameters/*[name])"), std::to_string(module.parameters().size()));
  const std::regex identifier("[_a-zA-Z][_a-zA-Z0-9]*");
  for (const cli::ModuleParameter* p : module.parameters())
  {
    EXPECT_TRUE(std::regex_match(p->name, identifier)) << p->name;
    EXPECT_TRUE(p->longflag.empty() || std::regex_match(p->longflag, identifier)) << p->longflag;
    EXPECT_FALSE(p->description.empty()) << p->name;
  }
}

TEST(ModuleXml, DeclaresTheInputOutputAndReturnParametersSlicerNeeds)
{
  EXPECT_EQ(xpath("count(//image[@type='scalar'][normalize-space(name)='inputVolume'][normalize-space(index)='0'])"),
            "1");
  EXPECT_EQ(xpath("count(//geometry[@type='model'][normalize-space(name)='outputModel'][normalize-space(index)='1']"
                  "[normalize-space(channel)='output'])"),
            "1");
  EXPECT_EQ(xpath("substring(//geometry[normalize-space(name)='outputModel']/@fileExtensions, 1, 4)"), ".vtp")
    << "Slicer passes a temporary file with the first listed extension";
  // A structure set or contour file is a file input of its own: the panel has no node for it.
  EXPECT_EQ(xpath("count(//file[normalize-space(name)='inputContours'][normalize-space(longflag)='--inputContours']"
                  "[normalize-space(channel)='input'][contains(@fileExtensions, '.dcm')])"),
            "1");
  for (const std::string name : { "triangles", "volume", "closed", "seconds", "structuresWritten" })
  {
    EXPECT_EQ(xpath("count(//parameters/*[normalize-space(name)='" + name +
                    "'][normalize-space(channel)='output'][not(flag) and not(longflag) and not(index)])"),
              "1")
      << name << " must be a return parameter";
  }
}

} // namespace
} // namespace slicemesh::testing

// The executable's side of Slicer's protocol and its command-line behaviour, for everything that
// happens before (or without) a successful reconstruction.
#include "CLITestSupport.h"
#include "ExitCodes.h"
#include "ModuleDescription.h"
#include "ModuleXml.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

const cli::ModuleDescription& module()
{
  static const cli::ModuleDescription description = cli::parseModuleDescription(cli::moduleXml());
  return description;
}

/** Exit codes of ExitCodes.h, as the README documents them. */

TEST(Executable, HelpMentionsEveryLongflagAndEveryIndexedArgument)
{
  const RunResult r = runSliceMesh("--help");
  EXPECT_EQ(r.exitCode, cli::Success);
  for (const cli::ModuleParameter* p : module().parameters())
  {
    if (!p->longflag.empty())
    {
      EXPECT_NE(r.out.find("--" + p->longflag), std::string::npos) << p->longflag;
    }
    if (!p->flag.empty())
    {
      EXPECT_NE(r.out.find("-" + p->flag + ","), std::string::npos) << p->flag;
    }
    if (p->index)
    {
      EXPECT_NE(r.out.find("<" + p->name + ">"), std::string::npos) << p->name;
    }
    if (!p->isReturnParameter() && !p->isBoolean() && !p->defaultValue.empty())
    {
      EXPECT_NE(r.out.find("Default: " + p->defaultValue), std::string::npos) << p->name;
    }
  }
  EXPECT_NE(r.out.find("(mm)"), std::string::npos) << "units appear in the help";
}

TEST(Executable, EveryOptionItAcceptsIsInTheXml)
{
  const std::set<std::string> builtIn = { "help", "xml", "version", "echo", "returnparameterfile",
                                          "processinformationaddress" };
  std::set<std::string> longflags;
  for (const cli::ModuleParameter* p : module().parameters())
  {
    longflags.insert(p->longflag);
  }
  const std::string help = runSliceMesh("--help").out;
  const std::regex option("(^|[ ,])--([A-Za-z_][A-Za-z0-9_]*)");
  int seen = 0;
  for (const std::string& line : linesOf(help))
  {
    if (line.rfind("  -", 0) != 0)
    {
      continue; // option lines start with two spaces and a dash; descriptions are indented further
    }
    for (auto it = std::sregex_iterator(line.begin(), line.end(), option); it != std::sregex_iterator(); ++it, ++seen)
    {
      const std::string name = (*it)[2];
      EXPECT_TRUE(longflags.count(name) || builtIn.count(name)) << "--" << name << " is not in the XML";
    }
  }
  EXPECT_GE(seen, 6);
}

TEST(Executable, AcceptsEveryParameterWithItsDefault)
{
  const fs::path folder = freshFolder("defaults");
  std::string arguments = "--echo";
  for (const cli::ModuleParameter* p : module().parameters())
  {
    if (p->isReturnParameter() || p->index || p->isBoolean() || p->tag == "point")
    {
      continue; // booleans default to false: absent; a point has no default and Slicer passes none
    }
    arguments += " --" + p->longflag + " " + quoted(p->defaultValue);
    if (!p->flag.empty())
    {
      EXPECT_EQ(runSliceMesh("-" + p->flag + " " + quoted(p->defaultValue) + " --help").exitCode, cli::Success) << p->flag;
    }
  }
  const fs::path output = folder / "out.vtp";
  const RunResult r = runSliceMesh(arguments + " " + quoted((folder / "missing.nrrd").string()) + " " +
                                   quoted(output.string()));
  // Accepted: the run gets as far as reading the (missing) input, and the defaults Slicer passes
  // cause no warning: stderr holds only the error.
  EXPECT_EQ(r.exitCode, cli::UnreadableInput) << r.err;
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  // And the defaults the executable uses are the XML's.
  for (const cli::ModuleParameter* p : module().parameters())
  {
    if (!p->isReturnParameter() && !p->index)
    {
      EXPECT_NE(r.out.find("  " + p->name + " = " + (p->isBoolean() ? "false" : p->defaultValue) + "\n"),
                std::string::npos)
        << p->name;
    }
  }
}

TEST(Executable, UnknownFlagIsAOneLineErrorWithItsOwnExitCode)
{
  const RunResult r = runSliceMesh("--no-such-option in.nrrd out.vtp");
  EXPECT_EQ(r.exitCode, cli::BadArguments);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("--no-such-option"), std::string::npos);
  EXPECT_EQ(r.out, "");
}

TEST(Executable, EnumerationValueOutsideItsElementsIsAnError)
{
  for (const cli::ModuleParameter* p : module().parameters())
  {
    if (p->isEnumeration())
    {
      const RunResult r = runSliceMesh("--" + p->longflag + " NotAnElement in.nrrd out.vtp");
      EXPECT_EQ(r.exitCode, cli::BadArguments) << p->name;
      EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
    }
  }
}

TEST(Executable, ValueOutsideItsConstraintsIsAnError)
{
  const RunResult r = runSliceMesh("--wallRowHeight -1 in.nrrd out.vtp");
  EXPECT_EQ(r.exitCode, cli::BadArguments);
  EXPECT_NE(r.err.find("wallRowHeight"), std::string::npos);
}

TEST(Executable, AcceptsAndIgnoresProcessInformationAddress)
{
  const fs::path folder = freshFolder("processinformation");
  const RunResult r = runSliceMesh("--processinformationaddress 0x7ffd0000 " +
                                   quoted((folder / "missing.nrrd").string()) + " " +
                                   quoted((folder / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::UnreadableInput) << r.err;
}

TEST(Executable, MissingInputFailsWithoutCreatingOutputOrReturnParameters)
{
  const fs::path folder = freshFolder("missing-input");
  const fs::path output = folder / "out.vtp";
  const fs::path params = folder / "out.params";
  const RunResult r = runSliceMesh("--returnparameterfile " + quoted(params.string()) + " " +
                                   quoted((folder / "missing.nii.gz").string()) + " " + quoted(output.string()));
  EXPECT_EQ(r.exitCode, cli::UnreadableInput);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("missing.nii.gz"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_FALSE(fs::exists(params));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 0) << "no temporary files";
}

TEST(Executable, ExistingOutputIsUntouchedOnFailure)
{
  const fs::path folder = freshFolder("untouched");
  const fs::path output = folder / "out.vtp";
  std::ofstream(output) << "precious";
  EXPECT_EQ(runSliceMesh(quoted((folder / "missing.nrrd").string()) + " " + quoted(output.string())).exitCode,
            cli::UnreadableInput);
  EXPECT_EQ(runSliceMesh("--label x " + quoted((folder / "missing.nrrd").string()) + " " + quoted(output.string()))
              .exitCode,
            cli::BadArguments);
  EXPECT_EQ(fileText(output), "precious");
}

TEST(Executable, LabelsZeroIsAUsageError)
{
  // 0 is the background: "no voxel has label 0" after reading the whole volume said the wrong thing.
  const fs::path folder = freshFolder("labels-zero");
  const RunResult r = runSliceMesh("--labels 1,0 " + quoted((folder / "missing.nrrd").string()) + " " +
                                   quoted((folder / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::BadArguments);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("background"), std::string::npos) << r.err;
}

/** A ball of label 1 in a label map: a run that is not refused meshes it. */
fs::path labelMapWithLabelOne(const fs::path& folder)
{
  const fs::path path = folder / "in.mha";
  writeMetaImage(path, { 16, 16, 16 }, { 1.0, 1.0, 1.0 },
                 [](int i, int j, int k)
                 { return (i - 7.5) * (i - 7.5) + (j - 7.5) * (j - 7.5) + (k - 7.5) * (k - 7.5) < 25.0 ? 1 : 0; });
  return path;
}

TEST(Executable, LabelBeyondAnIntIsAUsageError)
{
  // 4294967297 wrapped to label 1 and meshed it over the output; 4000000000 looked for label -294967296.
  const fs::path folder = freshFolder("label-beyond-int");
  const fs::path input = labelMapWithLabelOne(folder);
  const fs::path output = folder / "out.vtp";
  std::ofstream(output) << "an earlier run's mesh";
  for (const std::string label : { "-l 4294967297", "--label 4000000000", "--label=-2147483649", "--labels 4294967297",
                                   "--labels 1,4294967297", "--labels 99999999999999999999" })
  {
    const RunResult r = runSliceMesh(label + " " + quoted(input.string()) + " " + quoted(output.string()));
    EXPECT_EQ(r.exitCode, cli::BadArguments) << label << ": " << r.err;
    EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("is outside the range -2147483648 .. 2147483647"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(label.substr(0, label.find_first_of(" ="))), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fileText(output) == "an earlier run's mesh") << "the output was overwritten";
  // The ends of the range are labels (one that no voxel has).
  EXPECT_EQ(runSliceMesh("-l -2147483648 " + quoted(input.string()) + " " + quoted(output.string())).exitCode,
            cli::EmptySegmentation);
}

TEST(Executable, LabelsWithAnEmptyItemIsAUsageError)
{
  // ",,," meshed every label, "1,,3" labels 1 and 3: a slip in the list, taken without a word.
  const fs::path folder = freshFolder("labels-empty-item");
  const fs::path input = labelMapWithLabelOne(folder);
  const fs::path output = folder / "out.vtp";
  std::ofstream(output) << "an earlier run's mesh";
  for (const std::string labels : { ",,,", ",", "1,,3", "1,", ",1", "1, ,3" })
  {
    const RunResult r = runSliceMesh("--labels " + quoted(labels) + " " + quoted(input.string()) + " " +
                                     quoted(output.string()));
    EXPECT_EQ(r.exitCode, cli::BadArguments) << labels << ": " << r.err;
    EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("--labels: '" + labels + "' has an empty item"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fileText(output) == "an earlier run's mesh") << "the output was overwritten";
  // Empty as a whole: every label, as --help says.
  const RunResult every = runSliceMesh("--labels '' " + quoted(input.string()) + " " + quoted(output.string()));
  EXPECT_EQ(every.exitCode, cli::Success) << every.err;
}

TEST(Executable, LabelAndLabelsTogetherAreAUsageError)
{
  // One would be ignored without a word (the run meshed --labels and dropped --label).
  const fs::path folder = freshFolder("label-and-labels");
  const RunResult r = runSliceMesh("--label 2 --labels 1 " + quoted((folder / "missing.nrrd").string()) + " " +
                                   quoted((folder / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::BadArguments);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("--label and --labels"), std::string::npos) << r.err;
  EXPECT_EQ(runSliceMesh("--label 0 --labels 1 " + quoted((folder / "missing.nrrd").string()) + " " +
                         quoted((folder / "out.vtp").string()))
              .exitCode,
            cli::UnreadableInput)
    << "label 0 (every label, Slicer's default) goes with --labels";
  // Nor beside --splitLabels or --outputDirectory, which mesh every label (the run meshed them all).
  for (const std::string every : { std::string("--splitLabels"), "--outputDirectory " + quoted((folder / "labels").string()) })
  {
    const RunResult both = runSliceMesh("--label 2 " + every + " " + quoted((folder / "missing.nrrd").string()) + " " +
                                        quoted((folder / "out.vtp").string()));
    EXPECT_EQ(both.exitCode, cli::BadArguments) << every;
    EXPECT_EQ(linesOf(both.err).size(), 1u) << both.err;
    EXPECT_NE(both.err.find("--label picks one label"), std::string::npos) << both.err;
    EXPECT_EQ(runSliceMesh("--label 0 " + every + " " + quoted((folder / "missing.nrrd").string()) + " " +
                           quoted((folder / "out.vtp").string()))
                .exitCode,
              cli::UnreadableInput)
      << every;
  }
}

TEST(Executable, MissingOutputFolderIsAWriteFailureBeforeAnyWork)
{
  const fs::path folder = freshFolder("no-output-folder");
  const RunResult r = runSliceMesh(quoted((folder / "missing.nrrd").string()) + " " +
                                   quoted((folder / "nowhere" / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::WriteFailed);
  EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
}

TEST(Executable, ProgressOfAFailedRunIsMonotonicAndItsStageIsClosed)
{
  const fs::path folder = freshFolder("failed-progress");
  const RunResult r = runSliceMesh(quoted((folder / "missing.nrrd").string()) + " " + quoted((folder / "o.vtp").string()));
  const std::vector<double> progress = tagNumbers(r.out, "filter-progress");
  ASSERT_FALSE(progress.empty()) << r.out;
  for (std::size_t i = 1; i < progress.size(); ++i)
  {
    EXPECT_GE(progress[i], progress[i - 1]);
  }
  EXPECT_EQ(stageNames(r.out, "filter-start"), std::vector<std::string>{ "Reading" });
  EXPECT_EQ(stageNames(r.out, "filter-end"), std::vector<std::string>{ "Reading" });
}

TEST(Executable, VersionMatchesTheXml)
{
  const RunResult r = runSliceMesh("--version");
  EXPECT_EQ(r.exitCode, cli::Success);
  EXPECT_EQ(r.out, "SliceMesh " + module().version + "\n");
}

} // namespace
} // namespace slicemesh::testing

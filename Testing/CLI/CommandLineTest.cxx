// The table-driven parser, in process, against the real embedded XML and small hand-written ones.
#include "CommandLine.h"
#include "Sections/IntermediateSections.h"
#include "ModuleXml.h"
#include "Core/SliceMeshTypes.h"
#include "Finishing/SurfaceFinishing.h"

#include <gtest/gtest.h>

namespace slicemesh::cli
{
namespace
{

const ModuleDescription& sliceMesh()
{
  static const ModuleDescription module = parseModuleDescription(moduleXml());
  return module;
}

ParsedArguments parse(const std::vector<std::string>& arguments)
{
  return parseCommandLine(sliceMesh(), arguments);
}

std::string errorOf(const std::vector<std::string>& arguments)
{
  try
  {
    parse(arguments);
  }
  catch (const ArgumentError& e)
  {
    return e.what();
  }
  return "(no error)";
}

ModuleDescription moduleWith(const std::string& parameters)
{
  return parseModuleDescription("<?xml version=\"1.0\"?><executable><title>T</title><parameters><label>G</label>" +
                                parameters + "</parameters></executable>");
}

TEST(CommandLine, FillsDefaultsFromTheXml)
{
  const ParsedArguments a = parse({ "in.nrrd", "out.vtp" });
  EXPECT_EQ(a.text("inputVolume"), "in.nrrd");
  EXPECT_EQ(a.text("outputModel"), "out.vtp");
  EXPECT_EQ(a.text("inputKind"), "Automatic");
  EXPECT_EQ(a.integer("label"), 0);
  EXPECT_EQ(a.text("capPlacement"), "HalfSliceBeyond");
  EXPECT_EQ(a.text("coordinateSystem"), "LPS");
  EXPECT_FALSE(a.given("label"));
}

TEST(CommandLine, InputContoursStandsInForTheInputVolume)
{
  // 3D Slicer leaves out a volume nobody selected: the one positional argument is then the output.
  const ParsedArguments alone = parse({ "--inputContours", "RS.dcm", "out.vtp" });
  EXPECT_EQ(alone.text("inputContours"), "RS.dcm");
  EXPECT_EQ(alone.text("inputVolume"), "");
  EXPECT_EQ(alone.text("outputModel"), "out.vtp");
  const ParsedArguments both = parse({ "--inputContours", "RS.dcm", "ct.nrrd", "out.vtp" });
  EXPECT_EQ(both.text("inputVolume"), "ct.nrrd");
  EXPECT_EQ(both.text("outputModel"), "out.vtp");
  // Given empty (as a panel passes an unset file), it is no contour file and the volume is needed.
  EXPECT_NE(errorOf({ "--inputContours", "", "out.vtp" }).find("missing argument <outputModel>"), std::string::npos);
  EXPECT_NE(errorOf({ "out.vtp" }).find("missing argument <outputModel>"), std::string::npos);
}

TEST(CommandLine, AcceptsLongShortAndEqualsForms)
{
  EXPECT_EQ(parse({ "--label", "3", "in", "out.vtp" }).integer("label"), 3);
  EXPECT_EQ(parse({ "-l", "4", "in", "out.vtp" }).integer("label"), 4);
  EXPECT_EQ(parse({ "--label=5", "in", "out.vtp" }).integer("label"), 5);
  EXPECT_EQ(parse({ "in", "out.vtp", "--label", "-2" }).integer("label"), -2) << "a negative value is a value";
  EXPECT_TRUE(parse({ "--label", "3", "in", "out.vtp" }).given("label"));
  EXPECT_EQ(parse({ "--", "-odd-name.nrrd", "out.vtp" }).text("inputVolume"), "-odd-name.nrrd");
}

TEST(CommandLine, RejectsBadInputWithOneLineMessages)
{
  const std::vector<std::vector<std::string>> bad = {
    { "--nope", "in", "out.vtp" },                     // unknown option
    { "--label", "2.5", "in", "out.vtp" },             // not an integer
    { "--threshold", "abc", "in", "out.vtp" },         // not a number
    { "--coordinateSystem", "XYZ", "in", "out.vtp" },  // outside the enumeration
    { "--wallRowHeight", "-1", "in", "out.vtp" },      // below the minimum
    { "--wallRowHeight", "51", "in", "out.vtp" },      // above the maximum
    { "--label", "1", "--label", "2", "in", "out.vtp" }, // repeated
    { "in", "out.vtp", "extra" },                      // too many positional arguments
    { "in" },                                          // missing output
    { "in", "out.txt" },                               // output extension not in the XML
    { "in", "out.vtp", "--label" },                    // value missing
  };
  for (const auto& arguments : bad)
  {
    const std::string message = errorOf(arguments);
    EXPECT_NE(message, "(no error)") << arguments[0];
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(errorOf({ "--coordinateSystem", "XYZ", "in", "out.vtp" }).find("LPS, RAS"), std::string::npos);
}

TEST(CommandLine, AnIntegerIsAnInt)
{
  // An integer parameter without a range of its own has an int's: 4294967297 wrapped to 1.
  for (const std::string value : { "4294967297", "2147483648", "-2147483649", "99999999999999999999" })
    EXPECT_NE(errorOf({ "--label", value, "in", "out.vtp" }).find("--label (Label): " + value +
                                                                   " is outside the range -2147483648 .. 2147483647"),
              std::string::npos)
      << value;
  EXPECT_EQ(parse({ "--label", "2147483647", "in", "out.vtp" }).integer("label"), 2147483647);
  EXPECT_EQ(parse({ "--label", "-2147483648", "in", "out.vtp" }).integer("label"), -2147483648L);
  // Within the XML's own range, that range is the one named.
  EXPECT_NE(errorOf({ "--threads", "4294967297", "in", "out.vtp" }).find("outside the range 0 .. 256"),
            std::string::npos);
}

TEST(CommandLine, SectionOverlapOptionsReachTheirDefaultsAndRange)
{
  // The XML's defaults are the library's (UndersamplingOptions), so a run without the flags, or
  // Slicer passing the defaults, meshes as the library does.
  const ParsedArguments defaults = parse({ "in", "out.vtp" });
  EXPECT_EQ(defaults.number("sectionOverlap"), UndersamplingOptions().sectionOverlap);
  EXPECT_EQ(defaults.flag("refineWeakOverlap"), UndersamplingOptions().refineWeakOverlap);

  const ParsedArguments given = parse({ "--sectionOverlap", "0.5", "--refineWeakOverlap", "in", "out.vtp" });
  EXPECT_EQ(given.number("sectionOverlap"), 0.5);
  EXPECT_TRUE(given.flag("refineWeakOverlap"));
  EXPECT_EQ(parse({ "--sectionOverlap", "0.05", "in", "out.vtp" }).number("sectionOverlap"), 0.05);
  EXPECT_EQ(parse({ "--sectionOverlap", "0.95", "in", "out.vtp" }).number("sectionOverlap"), 0.95);

  // A share strictly between 0 and 1: 0 would be the paper's "any overlap", 1 asks for identical layers.
  for (const std::string value : { "0", "0.01", "0.99", "1", "-0.5", "abc" })
  {
    const std::string message = errorOf({ "--sectionOverlap", value, "in", "out.vtp" });
    EXPECT_NE(message.find("--sectionOverlap"), std::string::npos) << value << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(errorOf({ "--sectionOverlap", "1", "in", "out.vtp" }).find("outside the range 0.05 .. 0.95"),
            std::string::npos);
  EXPECT_NE(errorOf({ "--refineWeakOverlap=true", "in", "out.vtp" }), "(no error)") << "a switch takes no value";
}

TEST(CommandLine, SurfaceFinishingOptionsReachTheLibrarysDefaults)
{
  // The XML's defaults are SurfaceFinishingOptions' (the target edge length's 0 is "automatic":
  // automaticEdgeLength of the mask's spacing, resolved by the pipeline).
  const ParsedArguments defaults = parse({ "in", "out.vtp" });
  const SurfaceFinishingOptions library;
  EXPECT_EQ(defaults.text("surfaceFinish"), finishName(library.finish));
  EXPECT_EQ(defaults.integer("surfaceSmoothingIterations"), library.smoothing.iterations);
  EXPECT_EQ(defaults.number("surfaceSmoothingPassBand"), library.smoothing.passBand);
  EXPECT_EQ(defaults.number("targetEdgeLength"), 0.0);

  const ParsedArguments given = parse({ "--surfaceFinish", "Tiled", "--targetEdgeLength", "1.5",
                                        "--surfaceSmoothingIterations", "0", "--surfaceSmoothingPassBand", "0.1",
                                        "in", "out.vtp" });
  EXPECT_EQ(given.text("surfaceFinish"), "Tiled");
  EXPECT_EQ(given.number("targetEdgeLength"), 1.5);
  EXPECT_EQ(given.integer("surfaceSmoothingIterations"), 0);
  EXPECT_EQ(given.number("surfaceSmoothingPassBand"), 0.1);
  for (const char* finish : { "Remeshed", "Smoothed", "Tiled" })
    EXPECT_EQ(errorOf({ "--surfaceFinish", finish, "in", "out.vtp" }), "(no error)") << finish;
  // The parser checks the XML's inclusive range; the ends 0 and 1 are refused by the executable
  // (FinishingOptions.BadValuesAreUsageErrorsThatWriteNothing).
  for (const std::string value : { "-0.01", "1.01", "abc" })
    EXPECT_NE(errorOf({ "--surfaceSmoothingPassBand", value, "in", "out.vtp" }).find("--surfaceSmoothingPassBand"),
              std::string::npos)
      << value;
  EXPECT_NE(errorOf({ "--surfaceSmoothingIterations", "-1", "in", "out.vtp" }), "(no error)");
  EXPECT_NE(errorOf({ "--targetEdgeLength", "-0.5", "in", "out.vtp" }), "(no error)");
}

TEST(CommandLine, HelpNeedsNoPositionalArguments)
{
  EXPECT_TRUE(parse({ "--help" }).help);
  EXPECT_TRUE(parse({ "-h" }).help);
}

TEST(CommandLine, AcceptsSlicersBuiltInFlags)
{
  const ParsedArguments a =
    parse({ "--processinformationaddress", "0x1234", "--returnparameterfile", "/tmp/r.params", "--echo", "in",
            "out.vtp" });
  EXPECT_EQ(a.returnParameterFile, "/tmp/r.params");
  EXPECT_TRUE(a.echo);
}

TEST(CommandLine, ReturnParametersCannotBeGiven)
{
  EXPECT_NE(errorOf({ "--triangles", "5", "in", "out.vtp" }), "(no error)");
}

TEST(CommandLine, BooleansAreSwitchesThatMeanTrue)
{
  const ModuleDescription module = moduleWith(
    "<boolean><name>smooth</name><longflag>smooth</longflag><label>S</label><description>d</description>"
    "<default>false</default></boolean>");
  EXPECT_FALSE(parseCommandLine(module, {}).flag("smooth"));
  EXPECT_TRUE(parseCommandLine(module, { "--smooth" }).flag("smooth"));
  EXPECT_THROW(parseCommandLine(module, { "--smooth=false" }), ArgumentError);
}

TEST(ModuleDescriptionRules, RejectsXmlThatBreaksTheSlicerRules)
{
  const std::string tail = "<label>L</label><description>d</description><default>1</default>";
  EXPECT_THROW(moduleWith("<integer><name>a</name><flag>ab</flag>" + tail + "</integer>"), Error);
  EXPECT_THROW(moduleWith("<integer><name>a</name><flag>a</flag><index>0</index>" + tail + "</integer>"), Error);
  EXPECT_THROW(moduleWith("<integer><name>2a</name><longflag>a</longflag>" + tail + "</integer>"), Error);
  EXPECT_THROW(moduleWith("<boolean><name>b</name><longflag>b</longflag><label>L</label><description>d</description>"
                          "<default>true</default></boolean>"),
               Error);
  EXPECT_THROW(moduleWith("<string-enumeration><name>e</name><longflag>e</longflag><label>L</label>"
                          "<description>d</description><default>C</default><element>A</element>"
                          "<element>B</element></string-enumeration>"),
               Error);
  EXPECT_THROW(moduleWith("<integer><name>a</name><longflag>a</longflag>" + tail + "</integer>" +
                          "<integer><name>b</name><longflag>a</longflag>" + tail + "</integer>"),
               Error);
  EXPECT_THROW(parseModuleDescription("<executable><parameters>"), Error);
}

} // namespace
} // namespace slicemesh::cli

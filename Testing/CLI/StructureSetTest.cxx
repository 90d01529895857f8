// Structure sets and contour files through the executable: RTSTRUCTs synthesized with DCMTK, one
// mesh per ROI, each checked closed, manifold, free of self-intersections and outward, with its
// volume against the analytic one (caps half a slice beyond the end contours unless asked at them);
// and the files that must fail with one line and write nothing.
#include "CLITestSupport.h"
#include "DicomSeriesWriter.h"
#include "ExitCodes.h"
#include "MeshReader.h"
#include "Measures/MeshValidation.h"
#include "StructureSetWriter.h"
#include "TestContours.h"
#include "VolumeReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

constexpr double Spacing = 3.0; ///< slice spacing of the synthesized sets, mm

/** A valid closed surface: closed, manifold, checked free of self-intersections, outward. */
MeshValidation expectValid(const fs::path& path)
{
  const TriangleMesh mesh = readMesh(path.string()).mesh;
  const MeshValidation v = validateMesh(mesh);
  EXPECT_GT(v.triangles, 0u) << path;
  EXPECT_TRUE(v.closed()) << path << ": " << v.summary();
  EXPECT_TRUE(v.manifold()) << path << ": " << v.summary();
  EXPECT_TRUE(v.selfIntersectionChecked && v.selfIntersections == 0) << path << ": " << v.summary();
  EXPECT_TRUE(v.oriented()) << path << ": " << v.summary();
  return v;
}

long genus(const MeshValidation& v)
{
  return (2 * static_cast<long>(v.components) - v.eulerCharacteristic) / 2;
}

PlanarStructure roi(int number, const std::string& name, std::array<unsigned char, 3> rgb)
{
  PlanarStructure s;
  s.number = number;
  s.name = name;
  s.rgb = rgb;
  return s;
}

/** Annulus of radii 20 and 10 about (-40, 30) in 10 slices 0..27 mm: the hole as its own nested
 *  contour (stored with the same winding as the outer one: windings must not matter). */
PlanarStructure nestedAnnulus()
{
  PlanarStructure s = roi(1, "Annulus nested", { 250, 0, 0 });
  for (int k = 0; k < 10; ++k)
  {
    s.contours.push_back(circle(-40.0, 30.0, Spacing * k, 20.0));
    s.contours.push_back(circle(-40.0, 30.0, Spacing * k, 10.0));
  }
  return s;
}

/** The same annulus about (40, 30), each slice one keyhole contour with a zero-width channel. */
PlanarStructure keyholeAnnulusRoi()
{
  PlanarStructure s = roi(2, "Annulus keyhole", { 0, 250, 0 });
  for (int k = 0; k < 10; ++k)
    s.contours.push_back(keyholeAnnulus(40.0, 30.0, Spacing * k, 20.0, 10.0, 0.0));
  return s;
}

double annulusVolume()
{
  return (polygonArea(20.0) - polygonArea(10.0)) * 10 * Spacing; // 10 slices, half a slice beyond each end
}

struct SetRun
{
  RunResult result;
  fs::path folder;
};

SetRun meshSet(const std::string& test, const std::vector<PlanarStructure>& rois, const std::string& options = "",
            const std::vector<ContourItem>& extra = {})
{
  SetRun run;
  run.folder = freshFolder("StructureSet" + test);
  writeRTStructureSet((run.folder / "RS.dcm").string(), rois, extra);
  run.result = runSliceMesh(options + " --outputDirectory " + quoted((run.folder / "rois").string()) + " " +
                            quoted((run.folder / "RS.dcm").string()) + " " + quoted((run.folder / "all.vtp").string()));
  return run;
}

bool hasLine(const std::string& text, const std::string& part)
{
  for (const std::string& line : linesOf(text))
    if (line.find(part) != std::string::npos)
      return true;
  return false;
}

TEST(StructureSet, AnAnnulusWithItsHoleNestedOrAsAKeyholeIsATorusOfTheRightVolume)
{
  const SetRun run = meshSet("Annulus", { nestedAnnulus(), keyholeAnnulusRoi() }, "--report " + quoted((freshFolder("StructureSetAnnulusReport") / "r.json").string()));
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  for (const std::string file : { "001_Annulus_nested.vtp", "002_Annulus_keyhole.vtp" })
  {
    const MeshValidation v = expectValid(run.folder / "rois" / file);
    EXPECT_EQ(v.components, 1u) << file;
    EXPECT_EQ(genus(v), 1) << file << ": the hole goes through";
    // 2%: the caps half a slice beyond are joined to the end contours by a bevelled rim one wall
    // row wide (measured -1.5% at the 2 mm point spacing chosen here, as tiled; at the contours,
    // AtSlice, the tiling is exact); the finishing changes it by under 0.1%.
    EXPECT_NEAR(v.volume, annulusVolume(), 0.02 * annulusVolume()) << file;
  }
  EXPECT_TRUE(hasLine(run.result.err, "ROI 2 (Annulus keyhole): keyholes")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.out, "SliceMesh: ROI 1 (Annulus nested): volume")) << run.result.out;
  EXPECT_TRUE(hasLine(run.result.out, "half a slice beyond")) << run.result.out;
  // The merged model carries each ROI's colour.
  std::vector<std::array<unsigned char, 3>> colors;
  const MeshFile mergedFile = readMesh((run.folder / "all.vtp").string());
  const TriangleMesh& merged = mergedFile.mesh;
  colors = mergedFile.attributes.cellColors;
  ASSERT_EQ(colors.size(), merged.triangles.size());
  EXPECT_EQ(colors.front(), (std::array<unsigned char, 3>{ 250, 0, 0 }));
  EXPECT_EQ(colors.back(), (std::array<unsigned char, 3>{ 0, 250, 0 }));
}

TEST(StructureSet, AHollowOrganKeepsItsClosedCavity)
{
  // A wall around a lumen that starts and ends inside it: the lumen's contours, nested in 7 of the
  // 15 slices, make a closed cavity - a second, inward-facing surface - not a solid and not a tube.
  PlanarStructure hollow = roi(3, "Hollow", { 0, 0, 250 });
  for (int k = 0; k < 15; ++k)
  {
    hollow.contours.push_back(circle(0.0, -40.0, Spacing * k, 20.0));
    if (k >= 4 && k <= 10)
      hollow.contours.push_back(circle(0.0, -40.0, Spacing * k, 8.0, 48));
  }
  const SetRun run = meshSet("Hollow", { hollow });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const MeshValidation v = expectValid(run.folder / "rois" / "003_Hollow.vtp");
  EXPECT_EQ(v.components, 2u) << "the outer surface and the cavity's";
  EXPECT_EQ(genus(v), 0);
  // Each run of contours, the lumen's too, reaches half a slice beyond its end contours; 2.5%: the
  // caps' bevelled rims (see the annulus).
  const double expected = polygonArea(20.0) * 15 * Spacing - polygonArea(8.0, 48) * 7 * Spacing;
  EXPECT_NEAR(v.volume, expected, 0.025 * expected);
}

TEST(StructureSet, TheTilingLiesExactlyOnTheContoursInPatientSpace)
{
  // --surfaceFinish Tiled keeps every vertex of the prepared contours: the mesh must lie on the
  // contours (LPS), its caps half a slice beyond the end ones; in RAS x and y change sign.
  for (const std::string system : { "LPS", "RAS" })
  {
    const SetRun run = meshSet("Tiled" + system, { nestedAnnulus() }, "--surfaceFinish Tiled --coordinateSystem " + system);
    ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
    const TriangleMesh mesh = readMesh((run.folder / "rois" / "001_Annulus_nested.vtp").string()).mesh;
    const double sign = system == "RAS" ? -1.0 : 1.0;
    double minZ = 1e9, maxZ = -1e9, minRadius = 1e9, maxRadius = 0.0;
    for (const Point3& p : mesh.points)
    {
      minZ = std::min(minZ, p.z);
      maxZ = std::max(maxZ, p.z);
      const double radius = std::hypot(sign * p.x + 40.0, sign * p.y - 30.0);
      minRadius = std::min(minRadius, radius);
      maxRadius = std::max(maxRadius, radius);
    }
    EXPECT_NEAR(minZ, -0.5 * Spacing, 1e-9) << system;
    EXPECT_NEAR(maxZ, 27.0 + 0.5 * Spacing, 1e-9) << system;
    // Resampled keeping their area, the contours' points stay within a fraction of the chords'
    // sagitta (0.04 mm here) of the circles.
    EXPECT_NEAR(maxRadius, 20.0, 0.05) << system;
    EXPECT_GT(minRadius, 10.0 * std::cos(Pi / 96) - 0.05) << system << ": nothing inside the hole";
    EXPECT_LT(minRadius, 10.0 + 0.05) << system;
  }
}

TEST(StructureSet, CapsAtTheSliceCountTheVolumeFromTheFirstToTheLastContour)
{
  const SetRun run = meshSet("AtSlice", { nestedAnnulus() }, "--capPlacement AtSlice");
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const MeshValidation v = expectValid(run.folder / "rois" / "001_Annulus_nested.vtp");
  const double expected = (polygonArea(20.0) - polygonArea(10.0)) * 9 * Spacing;
  EXPECT_NEAR(v.volume, expected, 0.015 * expected);
  EXPECT_TRUE(hasLine(run.result.out, "end at the first and last contours")) << run.result.out;
}

TEST(StructureSet, HeldContoursKeepASquaresCornersOnTheSurface)
{
  // A 20 mm square on 7 slices: remeshed and smoothed as a whole, its corners are rounded; with
  // --holdContours every corner of the slices between the first and last is a vertex of the mesh.
  PlanarStructure square = roi(1, "Square", { 200, 0, 0 });
  for (int k = 0; k < 7; ++k)
    square.contours.push_back({ { -10, -10, Spacing * k }, { 10, -10, Spacing * k }, { 10, 10, Spacing * k }, { -10, 10, Spacing * k } });
  auto cornersOnTheMesh = [&](const std::string& options)
  {
    const SetRun run = meshSet(options.empty() ? "SquareRemeshed" : "SquareHeld", { square }, options);
    EXPECT_EQ(run.result.exitCode, cli::Success) << run.result.err;
    const fs::path file = run.folder / "rois" / "001_Square.vtp";
    expectValid(file);
    const TriangleMesh mesh = readMesh(file.string()).mesh;
    std::size_t found = 0;
    for (std::size_t k = 1; k + 1 < square.contours.size(); ++k)
      for (const Point3& corner : square.contours[k])
        found += std::any_of(mesh.points.begin(), mesh.points.end(),
                             [&](const Point3& p)
                             { return std::abs(p.x - corner.x) + std::abs(p.y - corner.y) + std::abs(p.z - corner.z) < 1e-6; });
    return found;
  };
  EXPECT_EQ(cornersOnTheMesh("--holdContours"), 20u);
  EXPECT_LT(cornersOnTheMesh(""), 20u) << "the default finish moves the corners";
}

TEST(StructureSet, SeveralContoursPerSliceBranchingAndDriftingContours)
{
  PlanarStructure two = roi(4, "Two columns", { 10, 20, 30 });
  PlanarStructure branch = roi(5, "Branch", { 40, 50, 60 });
  PlanarStructure drift = roi(6, "Drift", { 70, 80, 90 });
  for (int k = 0; k < 8; ++k)
  {
    const double z = Spacing * k;
    two.contours.push_back(circle(0.0, -60.0, z, 6.0, 48));
    two.contours.push_back(circle(20.0, -60.0, z, 6.0, 48));
    if (k < 4)
      branch.contours.push_back(circle(0.0, 60.0, z, 12.0, 64));
    else
    {
      branch.contours.push_back(circle(-7.0, 60.0, z, 5.0, 48));
      branch.contours.push_back(circle(7.0, 60.0, z, 5.0, 48));
    }
    drift.contours.push_back(circle(100.0 + 4.0 * k, 0.0, z, 5.0, 48)); // 4 mm per slice, radius 5
  }
  const SetRun run = meshSet("Branching", { two, branch, drift });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const MeshValidation columns = expectValid(run.folder / "rois" / "004_Two_columns.vtp");
  EXPECT_EQ(columns.components, 2u);
  const double columnsVolume = 2.0 * polygonArea(6.0, 48) * 8 * Spacing;
  EXPECT_NEAR(columns.volume, columnsVolume, 0.03 * columnsVolume);
  const MeshValidation branching = expectValid(run.folder / "rois" / "005_Branch.vtp");
  EXPECT_EQ(branching.components, 1u) << "the trunk and its two branches are one piece";
  EXPECT_EQ(genus(branching), 0);
  const MeshValidation drifting = expectValid(run.folder / "rois" / "006_Drift.vtp");
  EXPECT_EQ(drifting.components, 1u) << "circles overlapping from slice to slice make one slanted column";
}

TEST(StructureSet, AnROIBeyondAnyAnatomyFailsAloneAndTheOthersAreWritten)
{
  // Points over a kilometre from the origin are refused by the contour repair (its integer grid);
  // that ROI fails with its reason, as an ROI without contours does, not the whole run (exit 1).
  PlanarStructure far = roi(7, "Far", { 1, 2, 3 });
  for (int k = 0; k < 4; ++k)
    far.contours.push_back(circle(2.0e6, 0.0, Spacing * k, 10.0));
  const fs::path parameters = freshFolder("StructureSetFarParameters") / "out.params";
  const SetRun run = meshSet("Far", { nestedAnnulus(), far }, "--returnparameterfile " + quoted(parameters.string()));
  EXPECT_EQ(run.result.exitCode, cli::MeshingFailed) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "beyond the 1 km any anatomy lies within")) << run.result.err;
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "007_Far.vtp"));
  const MeshValidation annulus = expectValid(run.folder / "rois" / "001_Annulus_nested.vtp");
  // Slicer still gets the values of what was written (the file was not written at all).
  std::string volume;
  for (const auto& [name, value] : returnParameters(parameters))
    if (name == "volume")
      volume = value;
  ASSERT_FALSE(volume.empty());
  EXPECT_NEAR(std::stod(volume), annulus.volume, 1e-6 * annulus.volume);
}

TEST(StructureSet, AnROIWhoseSlicesAreAKilometreApartIsRefusedBeforeItIsTiled)
{
  // A set of one ROI drawn in two slices a kilometre apart (a stray contour's wrong position): the
  // gap is its slice spacing, tiled whole it would be a wall a kilometre high, and the run went on
  // until the machine ran out of memory. Refused at once, with the gap named; an existing output is
  // left as it was. The limit makes the test the same on any machine (about 64 GiB are needed).
  PlanarStructure stray = roi(3, "Stray", { 1, 2, 3 });
  stray.contours.push_back(circle(0.0, 0.0, 0.0, 10.0));
  stray.contours.push_back(circle(0.0, 0.0, 1.0e6, 10.0));
  const fs::path folder = freshFolder("StructureSetStray");
  writeRTStructureSet((folder / "RS.dcm").string(), { stray });
  const fs::path out = folder / "all.vtp";
  std::ofstream(out) << "kept";
  const RunResult r = runCommand("SLICEMESH_MEMORY_LIMIT_MB=4096 " + quoted(SLICEMESH_EXECUTABLE) + " " +
                                 quoted((folder / "RS.dcm").string()) + " " + quoted(out.string()));
  EXPECT_EQ(r.exitCode, cli::MeshingFailed) << r.err;
  EXPECT_TRUE(hasLine(r.err, "ROI 3 (Stray): tiled across its largest gap between slices (1000000.0 mm)")) << r.err;
  EXPECT_TRUE(hasLine(r.err, "of memory")) << r.err;
  EXPECT_EQ(fileText(out), "kept");
  // The same ROI with its slices 30 mm apart fits the same limit and is meshed.
  PlanarStructure near = roi(3, "Near", { 1, 2, 3 });
  near.contours.push_back(circle(0.0, 0.0, 0.0, 10.0));
  near.contours.push_back(circle(0.0, 0.0, 30.0, 10.0));
  writeRTStructureSet((folder / "RS-near.dcm").string(), { near });
  const RunResult meshed = runCommand("SLICEMESH_MEMORY_LIMIT_MB=4096 " + quoted(SLICEMESH_EXECUTABLE) + " " +
                                      quoted((folder / "RS-near.dcm").string()) + " " +
                                      quoted((folder / "near.vtp").string()));
  EXPECT_EQ(meshed.exitCode, 0) << meshed.err;
  expectValid(folder / "near.vtp");
}

TEST(StructureSet, ACoordinateOf1e300IsPrintedCompactlyInItsMessages)
{
  // A JSON slice at z = 1e300 (a value far past any anatomy, yet a finite double): the gap it makes
  // and the volume of a slab drawn there (in the summary and its warnings) were printed with all
  // their three hundred digits.
  const fs::path folder = freshFolder("StructureSetHugeCoordinate");
  const std::string triangle = R"("polygons": [[[0, 0], [5, 0], [5, 5]]])";
  std::ofstream(folder / "gap.json") << R"({"rois": [{"name": "Gap", "slices": [{"z": 0, )" << triangle << R"(}, {"z": 1, )"
                                     << triangle << R"(}, {"z": 1e300, )" << triangle << "}]}]}";
  std::ofstream(folder / "far.json") << R"({"rois": [{"name": "Near", "slices": [{"z": 0, )" << triangle << R"(}, {"z": 1, )"
                                     << triangle << R"(}]}, {"name": "Far", "slices": [{"z": 1e300, )" << triangle << "}]}]}";
  const RunResult gap = runSliceMesh(quoted((folder / "gap.json").string()) + " " + quoted((folder / "gap.vtp").string()));
  EXPECT_EQ(gap.exitCode, cli::MeshingFailed) << gap.err;
  EXPECT_TRUE(hasLine(gap.err, "ROI 1 (Gap): tiled across its largest gap between slices (1e+300 mm), about ")) << gap.err;
  const RunResult far = runSliceMesh(quoted((folder / "far.json").string()) + " " + quoted((folder / "far.vtp").string()));
  EXPECT_NE((far.out + far.err).find("ROI 2 (Far): volume "), std::string::npos) << far.out << far.err;
  const std::regex longNumber("[0-9]{20,}");
  for (const RunResult& r : { gap, far })
    EXPECT_FALSE(std::regex_search(r.out + r.err, longNumber)) << "a number of 20 digits or more in: " << r.err;
}

TEST(StructureSet, EmptyAndSingleSliceROIsAreReportedAndTheOthersWritten)
{
  PlanarStructure single = roi(8, "Single", { 1, 2, 3 });
  single.contours.push_back(circle(0.0, 100.0, 9.0, 10.0));
  const PlanarStructure empty = roi(9, "Nothing", { 4, 5, 6 });
  const SetRun run = meshSet("Empty", { nestedAnnulus(), single, empty });
  // An ROI without a closed contour (a point of interest, or empty) has no surface: skipped with a
  // warning, and the run succeeds.
  EXPECT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "SliceMesh: warning: ROI 9 (Nothing): has no closed contour")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.out, "SliceMesh: ROI 9 (Nothing): not meshed: no closed contour")) << run.result.out;
  EXPECT_TRUE(hasLine(run.result.err, "ROI 8 (Single): all contours lie in one slice")) << run.result.err;
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "009_Nothing.vtp"));
  expectValid(run.folder / "rois" / "001_Annulus_nested.vtp");
  const MeshValidation slab = expectValid(run.folder / "rois" / "008_Single.vtp");
  // One slice, as thick as the set's other ROIs' spacing; 10%: the smoothing rounds the rim of a
  // disc only 3 mm thick.
  const double expected = polygonArea(10.0) * Spacing;
  EXPECT_NEAR(slab.volume, expected, 0.1 * expected);
  double minZ = 1e9, maxZ = -1e9;
  for (const Point3& p : readMesh((run.folder / "rois" / "008_Single.vtp").string()).mesh.points)
  {
    minZ = std::min(minZ, p.z);
    maxZ = std::max(maxZ, p.z);
  }
  EXPECT_NEAR(minZ, 9.0 - 0.5 * Spacing, 0.5);
  EXPECT_NEAR(maxZ, 9.0 + 0.5 * Spacing, 0.5);
  expectValid(run.folder / "all.vtp");
}

TEST(StructureSet, AnROIThatFailsIsSaidOnce)
{
  // The only ROI, in one slice, with no other ROI to give it a thickness: its error is one line
  // (it was also repeated in the list of ROIs on stdout and in the run's last line); the last line
  // says how many ROIs failed.
  PlanarStructure single = roi(1, "Single", { 1, 2, 3 });
  single.contours.push_back(circle(3.0, 4.0, -7.5, 12.0));
  const SetRun run = meshSet("FailedOnce", { single });
  EXPECT_EQ(run.result.exitCode, cli::MeshingFailed) << run.result.err;
  std::size_t said = 0;
  for (const std::string& line : linesOf(run.result.out + run.result.err))
    said += line.find("the slice spacing is unknown") != std::string::npos;
  EXPECT_EQ(said, 1u) << run.result.out << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "SliceMesh: error: ROI 1 (Single): all 1 contour(s) lie in one slice")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.out, "SliceMesh: ROI 1 (Single): failed")) << run.result.out;
  EXPECT_EQ(linesOf(run.result.err).back(), "SliceMesh: error: 1 of 1 ROIs failed; nothing was written") << run.result.err;
}

TEST(StructureSet, SlicesSeveralOfTheSetsApartAreSlabsOfTheSetsSpacing)
{
  // Two ROIs on every slice, one every other slice, one in two slices 50 mm apart and one in a
  // single slice. The set's slice spacing is its ROIs' most common one (Spacing), not the median
  // of their spacings (2 Spacing here). The far-apart ROI (17 slices) is two slabs of that spacing, as
  // a planning system counts it, not a 51 mm column reaching 25 mm beyond each drawn slice; the
  // every-other-slice one keeps its own spacing (tiled across, as a planner interpolates).
  PlanarStructure everyOther = roi(3, "EveryOther", { 1, 2, 3 });
  for (int k = 0; k < 10; k += 2)
    everyOther.contours.push_back(circle(40.0, 40.0, Spacing * k, 8.0));
  PlanarStructure second = roi(4, "Second", { 1, 2, 3 });
  for (int k = 0; k < 6; ++k)
    second.contours.push_back(circle(40.0, -40.0, Spacing * k, 8.0));
  PlanarStructure apart = roi(5, "Apart", { 1, 2, 3 });
  apart.contours.push_back(circle(0.0, 80.0, 0.0, 10.0));
  apart.contours.push_back(circle(0.0, 80.0, 17 * Spacing, 10.0));
  PlanarStructure single = roi(6, "Single", { 1, 2, 3 });
  single.contours.push_back(circle(0.0, -80.0, 9.0, 10.0));
  const SetRun run = meshSet("SeveralApart", { nestedAnnulus(), everyOther, second, apart, single });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const double slab = polygonArea(10.0) * Spacing;
  const MeshValidation two = expectValid(run.folder / "rois" / "005_Apart.vtp");
  EXPECT_EQ(two.components, 2u);
  EXPECT_NEAR(two.volume, 2.0 * slab, 0.1 * slab);
  double minZ = 1e9, maxZ = -1e9;
  for (const Point3& p : readMesh((run.folder / "rois" / "005_Apart.vtp").string()).mesh.points)
    minZ = std::min(minZ, p.z), maxZ = std::max(maxZ, p.z);
  EXPECT_NEAR(minZ, -0.5 * Spacing, 0.5);
  EXPECT_NEAR(maxZ, 17.5 * Spacing, 0.5);
  const MeshValidation one = expectValid(run.folder / "rois" / "006_Single.vtp");
  EXPECT_NEAR(one.volume, slab, 0.1 * slab);
  const MeshValidation other = expectValid(run.folder / "rois" / "003_EveryOther.vtp");
  EXPECT_EQ(other.components, 1u);
}

TEST(StructureSet, AnROIIsNotSplitOnASpacingTheSetDoesNotClearlyHave)
{
  // An organ drawn every 3 mm and a target drawn every 1 mm (from an MR), and nothing else: the set
  // does not say which spacing its image has, so each ROI keeps its own. Stacked on the target's
  // 1 mm, the organ stopped and started again between its contours, a third of its volume. And
  // what is meshed of the organ does not depend on the other ROIs asked for with it.
  PlanarStructure organ = roi(1, "Organ", { 1, 2, 3 });
  for (int k = 0; k < 12; ++k)
    organ.contours.push_back(circle(0.0, 0.0, Spacing * k, 15.0));
  PlanarStructure target = roi(2, "Target", { 4, 5, 6 });
  for (int k = 0; k < 9; ++k)
    target.contours.push_back(circle(50.0, 0.0, Spacing / 3.0 * k, 5.0));
  const double prism = polygonArea(15.0) * 12.0 * Spacing; // half a slice beyond each end contour
  for (const std::string& chosen : { std::string(), std::string("--rois Organ") })
  {
    const SetRun run = meshSet(chosen.empty() ? "UnclearSpacing" : "UnclearSpacingOne", { organ, target }, chosen);
    ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
    EXPECT_FALSE(hasLine(run.result.err, "stops and starts again")) << run.result.err;
    const MeshValidation v = expectValid(run.folder / "rois" / "001_Organ.vtp");
    EXPECT_EQ(v.components, 1u) << chosen;
    EXPECT_NEAR(v.volume, prism, 0.01 * prism) << chosen;
  }
  // Two more ROIs every 1 mm make it the set's spacing: the organ is then drawn on every third of
  // its slices and counted as a planning system counts it, a slab of 1 mm per contour.
  PlanarStructure more = roi(3, "More", { 7, 8, 9 }), again = roi(4, "Again", { 7, 8, 9 });
  for (int k = 0; k < 9; ++k)
  {
    more.contours.push_back(circle(-50.0, 0.0, Spacing / 3.0 * k, 5.0));
    again.contours.push_back(circle(0.0, 50.0, Spacing / 3.0 * k, 5.0));
  }
  const SetRun run = meshSet("ClearSpacing", { organ, target, more, again }, "--rois Organ");
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const MeshValidation discs = expectValid(run.folder / "rois" / "001_Organ.vtp");
  EXPECT_EQ(discs.components, 12u);
  EXPECT_NEAR(discs.volume, prism / 3.0, 0.05 * prism / 3.0);
}

TEST(StructureSet, SmallROIsInOneSliceEncloseTheirSlabVolume)
{
  // A structure a few millimetres across drawn in one slice: its caps, domes half a slice high,
  // leave its tiling at 45-80% of the slab a planning system counts. The slab's volume is still
  // what the finished mesh must enclose.
  std::vector<PlanarStructure> rois{ nestedAnnulus() }; // the set's slice spacing
  const std::vector<double> radii{ 1.0, 1.5, 2.0, 3.0 };
  for (std::size_t i = 0; i < radii.size(); ++i)
  {
    PlanarStructure small = roi(static_cast<int>(i) + 2, "Small" + std::to_string(i), { 9, 9, 9 });
    small.contours.push_back(circle(20.0 + 10.0 * static_cast<double>(i), -30.0, 12.0, radii[i], 64));
    rois.push_back(small);
  }
  const SetRun run = meshSet("SmallSingleSlice", rois);
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  for (std::size_t i = 0; i < radii.size(); ++i)
  {
    const fs::path file = run.folder / "rois" / ("00" + std::to_string(i + 2) + "_Small" + std::to_string(i) + ".vtp");
    const MeshValidation v = expectValid(file);
    const double slab = polygonArea(radii[i], 64) * Spacing;
    // 0.5%: the finishing offsets to the volume exactly; what is left is the file's float coordinates.
    EXPECT_NEAR(v.volume, slab, 0.005 * slab) << file;
  }
}

TEST(StructureSet, UnevenSpacingAndASelfCrossingContourAreToleratedWithWarnings)
{
  PlanarStructure uneven = roi(10, "Uneven", { 9, 9, 9 });
  for (double z : { 0.0, 2.9, 6.1, 9.0, 12.0 })
    uneven.contours.push_back(circle(0.0, 0.0, z, 10.0));
  PlanarStructure crossing = roi(11, "Crossing", { 8, 8, 8 });
  for (int k = 0; k < 5; ++k)
  {
    Polygon3 c = circle(60.0, 0.0, Spacing * k, 10.0);
    if (k == 2) // a loop drawn over itself: two points swapped make the contour cross itself
      std::swap(c[10], c[12]);
    crossing.contours.push_back(c);
  }
  const SetRun run = meshSet("Uneven", { uneven, crossing });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "ROI 10 (Uneven): uneven slice spacing")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "ROI 11 (Crossing): contours crossing in 1 slice (z = 6 mm)"))
    << run.result.err;
  const MeshValidation a = expectValid(run.folder / "rois" / "010_Uneven.vtp");
  const double expected = polygonArea(10.0) * (12.0 + 2.95); // from -half to +half of the median gap
  EXPECT_NEAR(a.volume, expected, 0.03 * expected);
  expectValid(run.folder / "rois" / "011_Crossing.vtp");
}

TEST(StructureSet, PointsAndOpenContoursAreSkippedWithAWarningAndRoisPicksByNameOrNumber)
{
  const SetRun run = meshSet("Rois", { nestedAnnulus(), keyholeAnnulusRoi() }, "--rois 'annulus keyhole'",
                          { { 2, "POINT", { { 40, 30, 3 } } }, { 1, "OPEN_PLANAR", circle(0, 0, 0, 3, 8) } });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "ROI 2 (Annulus keyhole): 1 POINT item(s) skipped")) << run.result.err;
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "001_Annulus_nested.vtp"));
  expectValid(run.folder / "rois" / "002_Annulus_keyhole.vtp");

  const fs::path folder = freshFolder("StructureSetRoisMissing");
  const RunResult missing = runSliceMesh("--rois Heart " + quoted((run.folder / "RS.dcm").string()) + " " +
                                         quoted((folder / "out.vtp").string()));
  EXPECT_EQ(missing.exitCode, cli::EmptySegmentation) << missing.err;
  EXPECT_TRUE(hasLine(missing.err, "no ROI is called or numbered 'Heart'")) << missing.err;
  EXPECT_TRUE(fs::is_empty(folder));
}

TEST(StructureSet, APointOfInterestIsSkippedUnlessAskedForByName)
{
  // Nearly every plan's structure set holds an isocentre or a marker: POINT items only.
  const PlanarStructure marker = roi(7, "Iso", { 255, 0, 0 });
  const fs::path results = freshFolder("StructureSetMarkerResults") / "r.txt";
  const SetRun run = meshSet("Marker", { nestedAnnulus(), marker },
                             "--report " + quoted((freshFolder("StructureSetMarkerReport") / "report.json").string()) +
                               " --returnparameterfile " + quoted(results.string()),
                             { { 7, "POINT", { { 40, 30, 3 } } } });
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "ROI 7 (Iso): has no closed contour (a point of interest, or empty): not meshed"))
    << run.result.err;
  expectValid(run.folder / "rois" / "001_Annulus_nested.vtp");
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "007_Iso.vtp"));
  bool oneWritten = false;
  for (const auto& [name, value] : returnParameters(results))
    oneWritten = oneWritten || (name == "structuresWritten" && value == "1");
  EXPECT_TRUE(oneWritten) << "the return parameters of a run that succeeded";
  const std::string report = fileText(fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "StructureSetMarkerReport" / "report.json");
  EXPECT_NE(report.find("\"droppedBecause\": \"no closed contour\""), std::string::npos) << report;

  // Asked for by name, it is a failure that says why; alone, there is nothing to mesh.
  const fs::path folder = freshFolder("StructureSetMarkerAsked");
  const RunResult asked = runSliceMesh("--rois Iso " + quoted((run.folder / "RS.dcm").string()) + " " +
                                       quoted((folder / "out.vtp").string()));
  EXPECT_EQ(asked.exitCode, cli::MeshingFailed) << asked.err;
  EXPECT_TRUE(hasLine(asked.err, "ROI 7 (Iso): has no contours")) << asked.err;
  EXPECT_FALSE(fs::exists(folder / "out.vtp"));
  const SetRun alone = meshSet("MarkerAlone", { marker }, "", { { 7, "POINT", { { 40, 30, 3 } } } });
  EXPECT_EQ(alone.result.exitCode, cli::EmptySegmentation) << alone.result.err;
  EXPECT_TRUE(hasLine(alone.result.err, "has a closed contour; nothing to mesh")) << alone.result.err;
  EXPECT_FALSE(fs::exists(alone.folder / "all.vtp"));
}

TEST(StructureSet, ANameInLatin1IsUtf8InTheOutputTheReportAndItsFileName)
{
  // No Specific Character Set, as the writer leaves it: the byte 0xFC beyond ASCII is Latin-1's u umlaut.
  PlanarStructure latin1 = nestedAnnulus();
  latin1.name = "R\xFC" "ckenmark/C1";
  const fs::path report = freshFolder("StructureSetLatin1Report") / "report.json";
  const SetRun run = meshSet("Latin1", { latin1 }, "--report " + quoted(report.string()));
  ASSERT_EQ(run.result.exitCode, cli::Success) << run.result.err;
  const std::string utf8 = "R\xC3\xBC" "ckenmark/C1";
  EXPECT_TRUE(hasLine(run.result.out, "SliceMesh: ROI 1 (" + utf8 + "): volume")) << run.result.out;
  const std::string json = fileText(report);
  EXPECT_NE(json.find("\"name\": \"" + utf8 + "\""), std::string::npos) << json;
  EXPECT_EQ(json.find('\xFC'), std::string::npos) << "no Latin-1 byte left in the report";
  // The letter as UTF-8 in the file name too; the slash, which would make a folder, becomes '_'.
  expectValid(run.folder / "rois" / ("001_" + std::string("R\xC3\xBC" "ckenmark_C1") + ".vtp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(run.folder / "rois"), fs::directory_iterator()), 1);
}

TEST(StructureSet, AnEarlierMeshOfAnROIThatFailsNowIsKeptAndSaidToBeItsOwn)
{
  // A run whose ROI B fails keeps B's mesh from the run before (nothing the user had is lost) and
  // says it is an earlier run's mesh of an ROI that failed, not of another ROI.
  const fs::path folder = freshFolder("StructureSetEarlierFailed");
  auto writeSet = [&](const std::string& bCoordinate)
  {
    std::ofstream(folder / "set.json")
      << R"({ "rois": [ { "name": "A", "slices": [ { "z": 0, "polygons": [ [[0, 0], [8, 0], [8, 8], [0, 8]] ] },)"
      << R"( { "z": 2, "polygons": [ [[0, 0], [8, 0], [8, 8], [0, 8]] ] } ] },)"
      << R"( { "name": "B", "slices": [ { "z": 0, "polygons": [ [[20, 0], [28, 0], [28, 8], [20, )" << bCoordinate
      << R"(]] ] }, { "z": 2, "polygons": [ [[20, 0], [28, 0], [28, 8], [20, 8]] ] } ] } ] })";
  };
  const std::string run = "--outputDirectory " + quoted((folder / "rois").string()) + " " +
                          quoted((folder / "set.json").string()) + " " + quoted((folder / "all.vtp").string());
  writeSet("8");
  ASSERT_EQ(runSliceMesh(run).exitCode, cli::Success);
  const std::string before = fileText(folder / "rois" / "002_B.vtp");
  writeSet("\"8\"");
  const RunResult failed = runSliceMesh(run);
  EXPECT_EQ(failed.exitCode, cli::MeshingFailed) << failed.err;
  EXPECT_TRUE(hasLine(failed.err, "error: ROI 2 (B): rois[1].slices[0].polygons[0]: a coordinate is not a number"))
    << failed.err;
  EXPECT_NE(failed.err.find("still holds 1 mesh file(s) of ROIs that failed in this run (first: 002_B.vtp)"),
            std::string::npos)
    << failed.err;
  EXPECT_EQ(failed.err.find("of other ROIs"), std::string::npos) << failed.err;
  EXPECT_EQ(fileText(folder / "rois" / "002_B.vtp"), before);
  expectValid(folder / "rois" / "001_A.vtp");
}

TEST(StructureSet, ROINumbersOfZeroOfASignAndOfManyDigitsAreAllPaddedAndSortInOrder)
{
  // ROI 0 was written as '0_Zero.vtp' and ROI -3 as '-3_Negative.vtp' beside a number of more than
  // three digits (which left every file unpadded), and as '-03_Negative.vtp' beside '007_Seven.vtp'.
  const fs::path folder = freshFolder("StructureSetFileNumbers");
  auto meshFiles = [&](const std::vector<std::pair<int, std::string>>& rois)
  {
    std::ostringstream json;
    json << R"({ "rois": [ )";
    double x = 0.0;
    for (const auto& [number, name] : rois)
    {
      const std::string square = "[ [[" + std::to_string(x) + ", 0], [" + std::to_string(x + 8) + ", 0], [" +
                                 std::to_string(x + 8) + ", 8], [" + std::to_string(x) + ", 8]] ]";
      json << (x > 0.0 ? ", " : "") << R"({ "number": )" << number << R"(, "name": ")" << name
           << R"(", "slices": [ { "z": 0, "polygons": )" << square << R"( }, { "z": 2, "polygons": )" << square
           << " } ] }";
      x += 20.0;
    }
    json << " ] }";
    std::ofstream(folder / "set.json") << json.str();
    fs::remove_all(folder / "rois");
    const RunResult r = runSliceMesh("--outputDirectory " + quoted((folder / "rois").string()) + " " +
                                     quoted((folder / "set.json").string()) + " " + quoted((folder / "all.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << r.err;
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder / "rois"))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end()); // as a file browser lists them
    return names;
  };
  const std::vector<std::pair<int, std::string>> small{ { 7, "Seven" }, { -12, "Twelve below" }, { 0, "Zero" },
                                                         { -3, "Negative" } };
  EXPECT_EQ(meshFiles(small), (std::vector<std::string>{ "-003_Negative.vtp", "-012_Twelve_below.vtp", "000_Zero.vtp",
                                                        "007_Seven.vtp" }));
  std::vector<std::pair<int, std::string>> large = small;
  large.emplace_back(1000000, "Million");
  EXPECT_EQ(meshFiles(large), (std::vector<std::string>{ "-0000003_Negative.vtp", "-0000012_Twelve_below.vtp",
                                                        "0000000_Zero.vtp", "0000007_Seven.vtp", "1000000_Million.vtp" }));
}

TEST(StructureSet, TwoROIsOfOneNumberFailWithOneWarningAndTheOthersAreWritten)
{
  // Which of the two ROIs numbered 1 a contour of ROI 1 belongs to cannot be told: neither may get
  // the other's contours (both went to the second, unsaid).
  PlanarStructure a = nestedAnnulus();
  a.name = "A";
  PlanarStructure b = keyholeAnnulusRoi();
  b.number = 1;
  b.name = "B";
  PlanarStructure kept = keyholeAnnulusRoi();
  kept.number = 4;
  kept.name = "Kept";
  const fs::path report = freshFolder("StructureSetSharedNumberReport") / "report.json";
  const SetRun run = meshSet("SharedNumber", { a, b, kept }, "--report " + quoted(report.string()));
  EXPECT_EQ(run.result.exitCode, cli::MeshingFailed) << run.result.err;
  std::size_t warnings = 0;
  for (const std::string& line : linesOf(run.result.err))
    warnings += line.find("warning") != std::string::npos &&
                line.find("ROI number 1 is given to 2 ROIs, 'A' and 'B'") != std::string::npos;
  EXPECT_EQ(warnings, 1u) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "error: ROI 1 (A): ROI number 1 is also given to 'B'")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "error: ROI 1 (B): ROI number 1 is also given to 'A'")) << run.result.err;
  EXPECT_TRUE(hasLine(run.result.err, "2 of 3 ROIs failed; the others were written")) << run.result.err;
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "001_A.vtp"));
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "001_B.vtp"));
  const MeshValidation v = expectValid(run.folder / "rois" / "004_Kept.vtp");
  EXPECT_NEAR(v.volume, annulusVolume(), 0.02 * annulusVolume());
  const std::string json = fileText(report);
  EXPECT_NE(json.find("ROI number 1 is also given to 'B'"), std::string::npos) << json;
  EXPECT_NE(json.find("ROI number 1 is also given to 'A'"), std::string::npos) << json;
}

TEST(StructureSet, AContourValueThatIsNoNumberFailsItsROIAloneAndTheOthersAreWritten)
{
  // A decimal comma in one contour of ROI 2 (a system set to a European locale writes one): ROI 2
  // fails with one line naming it and the value, ROI 1 is written, the run ends as when any ROI fails.
  ContourItem comma{ 2, "CLOSED_PLANAR", {} };
  comma.contourData = "40\\30\\0\\59,5\\30\\0\\40\\50\\0";
  const SetRun run = meshSet("DecimalComma", { nestedAnnulus(), keyholeAnnulusRoi() }, "", { comma });
  EXPECT_EQ(run.result.exitCode, cli::MeshingFailed) << run.result.err;
  std::size_t lines = 0;
  for (const std::string& line : linesOf(run.result.err))
    lines += line.rfind("SliceMesh: error: ROI 2 (Annulus keyhole): ", 0) == 0 && line.find("'59,5'") != std::string::npos;
  EXPECT_EQ(lines, 1u) << run.result.err;
  const MeshValidation v = expectValid(run.folder / "rois" / "001_Annulus_nested.vtp");
  EXPECT_NEAR(v.volume, annulusVolume(), 0.02 * annulusVolume());
  EXPECT_FALSE(fs::exists(run.folder / "rois" / "002_Annulus_keyhole.vtp"));
}

TEST(StructureSet, AStructureSetWithoutPreambleIsRecognisedGivenOrAsInputContours)
{
  // The dataset alone, as older systems write it: no 128-byte preamble, no "DICM", no meta header
  // (whose length its first element, (0002,0000) UL at byte 132, gives).
  const fs::path folder = freshFolder("StructureSetNoPreamble");
  writeRTStructureSet((folder / "part10.dcm").string(), { nestedAnnulus() });
  const std::string part10 = fileText(folder / "part10.dcm");
  ASSERT_EQ(part10.compare(128, 4, "DICM"), 0);
  std::uint32_t metaLength = 0;
  std::memcpy(&metaLength, part10.data() + 140, 4);
  std::ofstream(folder / "RS.dcm", std::ios::binary) << part10.substr(144 + metaLength);
  for (const std::string& input : { quoted((folder / "RS.dcm").string()), "--inputContours " + quoted((folder / "RS.dcm").string()) })
  {
    fs::remove_all(folder / "rois");
    const RunResult run = runSliceMesh(input + " --outputDirectory " + quoted((folder / "rois").string()) + " " +
                                       quoted((folder / "all.vtp").string()));
    ASSERT_EQ(run.exitCode, cli::Success) << input << ": " << run.err;
    const MeshValidation v = expectValid(folder / "rois" / "001_Annulus_nested.vtp");
    EXPECT_NEAR(v.volume, annulusVolume(), 0.02 * annulusVolume()) << input;
  }
  // In a folder given as the input, as a planning system exports a plan: the folder's structure set.
  fs::create_directories(folder / "export");
  fs::copy_file(folder / "RS.dcm", folder / "export" / "RS.dcm");
  fs::remove_all(folder / "rois");
  const RunResult run = runSliceMesh(quoted((folder / "export").string()) + " --outputDirectory " +
                                     quoted((folder / "rois").string()) + " " + quoted((folder / "all.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err;
  EXPECT_TRUE(hasLine(run.err, "holds a structure set, RS.dcm: its ROIs are meshed")) << run.err;
  expectValid(folder / "rois" / "001_Annulus_nested.vtp");
}

TEST(StructureSet, FilesThatAreNoStructureSetOrAreCutShortFailWithOneLineAndWriteNothing)
{
  const fs::path folder = freshFolder("StructureSetBadFiles");
  writeRTStructureSet((folder / "RS.dcm").string(), { nestedAnnulus() });
  fs::copy_file(folder / "RS.dcm", folder / "cut.dcm");
  fs::resize_file(folder / "cut.dcm", fs::file_size(folder / "RS.dcm") / 2);
  std::ofstream(folder / "text.json") << "{ \"rois\": 12 }";
  std::ofstream(folder / "plain.txt") << "not contours";
  // Legacy VTK cell lists shorter than declared (VTK 9.1's reader crashed on it), with a cell
  // running past the list's end, or naming a point the file does not have.
  const std::string points = "# vtk DataFile Version 4.2\nRing\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
                             "0 0 0 4 0 0 4 4 0 0 4 0\n";
  std::ofstream(folder / "short.vtk") << points << "LINES 1 34\n5 0 1 2 3 0\n";
  std::ofstream(folder / "overrun.vtk") << points << "LINES 1 6\n9 0 1 2 3 0\n";
  std::ofstream(folder / "point.vtk") << points << "LINES 1 6\n5 0 1 2 7 0\n";
  // A list header with a stray character after its size (VTK 9.1 read past the list and crashed).
  std::ofstream(folder / "header.vtk") << points << "LINES 1 6@\n5 0 1 2 3 0\n";
  // The header's size on the next line, as VTK reads it, and the list then short of it.
  std::ofstream(folder / "split.vtk") << points << "LINES 52\n 12 0 1 2 3 0\n5 0 1 2 3\n";
  // A keyword with a stray character (VTK 9.1 took it for LINES and read past its buffer).
  std::ofstream(folder / "keyword.vtk") << points << "LINES^ 2 12\n5 0 1 2 300\n5 4 5 6 7 4\n";
  for (const std::string& arguments :
       { quoted((folder / "cut.dcm").string()), "--inputContours " + quoted((folder / "plain.txt").string()),
         quoted((folder / "short.vtk").string()), quoted((folder / "overrun.vtk").string()),
         quoted((folder / "point.vtk").string()), quoted((folder / "header.vtk").string()),
         quoted((folder / "split.vtk").string()), quoted((folder / "keyword.vtk").string()),
         "--contourFormat RTSTRUCT " + quoted((folder / "text.json").string()), quoted((folder / "text.json").string()) })
  {
    const fs::path out = folder / "out";
    const RunResult r = runSliceMesh(arguments + " --outputDirectory " + quoted(out.string()) + " " +
                                     quoted((folder / "mesh.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::UnreadableInput) << arguments << ": " << r.err;
    ASSERT_EQ(linesOf(r.err).size(), 1u) << arguments << ": " << r.err;
    EXPECT_EQ(r.err.rfind("SliceMesh: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(folder / "mesh.vtp")) << arguments;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << arguments;
  }
}

/** An oblique slice frame: the slices tilted 30 degrees about x and 20 about z (LPS). */
struct ObliqueFrame
{
  Vector3 e1, e2, normal;
  ObliqueFrame()
  {
    const double a = 30.0 * Pi / 180.0, b = 20.0 * Pi / 180.0;
    e1 = { std::cos(b), std::sin(b), 0.0 };
    e2 = { -std::sin(b) * std::cos(a), std::cos(b) * std::cos(a), std::sin(a) };
    normal = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
  }
};

/** A cylinder of radius r on the oblique slices: circles on the slices `ks` (3 mm apart, the first
 *  about `centre`), the points rounded to 0.01 mm as a planning system writes them. */
PlanarStructure obliqueCylinder(int number, const std::string& name, const Vector3& centre, double r,
                                const std::vector<int>& ks = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 })
{
  const ObliqueFrame f;
  PlanarStructure s = roi(number, name, { 200, 100, 0 });
  for (int k : ks)
  {
    Polygon3 contour;
    for (int i = 0; i < 96; ++i)
    {
      const double c = r * std::cos(2.0 * Pi * i / 96), t = r * std::sin(2.0 * Pi * i / 96), h = Spacing * k;
      Vector3 p;
      for (int row = 0; row < 3; ++row)
        p[row] = std::round(100.0 * (centre[row] + c * f.e1[row] + t * f.e2[row] + h * f.normal[row])) / 100.0;
      contour.push_back({ p[0], p[1], p[2] });
    }
    s.contours.push_back(contour);
  }
  return s;
}

/** A small NRRD image (LPS) whose voxel axes are the columns of `axes`, `spacing` mm apart. */
void writeReferenceImage(const fs::path& path, const std::array<Vector3, 3>& axes, const Vector3& spacing)
{
  std::ofstream file(path, std::ios::binary);
  file << "NRRD0004\ntype: unsigned char\ndimension: 3\nspace: left-posterior-superior\nsizes: 4 4 4\n"
       << "space directions:";
  file.precision(17);
  for (int axis = 0; axis < 3; ++axis)
    file << " (" << spacing[axis] * axes[axis][0] << "," << spacing[axis] * axes[axis][1] << ","
         << spacing[axis] * axes[axis][2] << ")";
  file << "\nspace origin: (-30,20,50)\nencoding: raw\n\n" << std::string(64, '\0');
}

TEST(StructureSet, ObliqueContoursStackAlongTheSlicesOfTheImageTheyWereDrawnOn)
{
  // The CT the structure set was drawn on, given beside it: its slice direction and spacing stack
  // the contours; the mesh lies on the contours and holds the planning-system volume. Contoured on
  // every other slice but one, the contours alone would tell a 6 mm spacing (the ends 3 mm
  // beyond the end contours, 10% more volume); the image tells 3 mm, the gaps one slice missing.
  const ObliqueFrame f;
  const Vector3 centre{ -20.0, 40.0, 60.0 };
  const double r = 15.0;
  const fs::path folder = freshFolder("StructureSetOblique");
  writeRTStructureSet((folder / "RS.dcm").string(), { obliqueCylinder(1, "Oblique", centre, r, { 0, 1, 3, 5, 7, 9 }) });
  writeReferenceImage(folder / "ct.nrrd", { f.e1, f.e2, f.normal }, { 0.8, 0.8, Spacing });
  const RunResult run = runSliceMesh("--inputContours " + quoted((folder / "RS.dcm").string()) + " " +
                                     quoted((folder / "ct.nrrd").string()) + " " + quoted((folder / "mesh.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err;
  EXPECT_FALSE(hasLine(run.err, "not on the slices")) << run.err;
  EXPECT_TRUE(hasLine(run.err, "one slice missing, tiled across it")) << run.err;
  const MeshValidation v = expectValid(folder / "mesh.vtp");
  EXPECT_EQ(v.components, 1u);
  const double expected = polygonArea(r) * 10 * Spacing; // half a slice beyond each end contour
  EXPECT_NEAR(v.volume, expected, 0.02 * expected); // 2%: as the annulus (the caps' bevelled rims)
  // Where the contours are: along the normal from half a slice before the first contour to half a
  // slice after the last, within the circles' radius of their axis (0.5 mm: the finishing's
  // smoothing of the rims).
  double lowest = 1e9, highest = -1e9, widest = 0.0;
  for (const Point3& p : readMesh((folder / "mesh.vtp").string()).mesh.points)
  {
    const Vector3 d{ p.x - centre[0], p.y - centre[1], p.z - centre[2] };
    const double h = d[0] * f.normal[0] + d[1] * f.normal[1] + d[2] * f.normal[2];
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
    widest = std::max(widest, std::hypot(d[0] - h * f.normal[0], d[1] - h * f.normal[1], d[2] - h * f.normal[2]));
  }
  EXPECT_NEAR(lowest, -0.5 * Spacing, 0.5);
  EXPECT_NEAR(highest, 9.5 * Spacing, 0.5);
  EXPECT_NEAR(widest, r, 0.5);
}

TEST(StructureSet, ADicomFolderOfACTSeriesAndItsStructureSetMeshesTheROIsOnTheSeriesSlices)
{
  // A plan exported as planning systems do: the CT slices and the RTSTRUCT in one folder, given as the
  // input. The ROIs are meshed (not the CT), stacked on the series' slices: contoured on every other
  // slice but one, the series tells 3 mm where the contours alone would tell 6.
  const ObliqueFrame f;
  const Vector3 centre{ -20.0, 40.0, 60.0 };
  const double r = 15.0;
  const fs::path folder = freshFolder("StructureSetDicomFolder");
  auto ct = testing::CTVolume::New();
  ct->SetRegions(testing::CTVolume::SizeType{ { 64, 64, 12 } });
  ct->Allocate(true);
  testing::CTVolume::SpacingType spacing;
  spacing[0] = spacing[1] = 0.8, spacing[2] = Spacing;
  ct->SetSpacing(spacing);
  testing::CTVolume::DirectionType direction;
  testing::CTVolume::PointType origin; // the slice before the first contour, the circles in the middle
  for (int row = 0; row < 3; ++row)
  {
    direction[row][0] = f.e1[row], direction[row][1] = f.e2[row], direction[row][2] = f.normal[row];
    origin[row] = centre[row] - 25.2 * (f.e1[row] + f.e2[row]) - Spacing * f.normal[row];
  }
  ct->SetDirection(direction);
  ct->SetOrigin(origin);
  testing::writeCTSeries(ct, folder / "CT");
  // The structure set in the series' Frame of Reference (the UID the DICOM writer gave the slices).
  const std::string frame = readVolumeGeometry((folder / "CT").string()).frameOfReference;
  ASSERT_FALSE(frame.empty());
  writeRTStructureSet((folder / "CT" / "RS.dcm").string(), { obliqueCylinder(1, "Oblique", centre, r, { 0, 1, 3, 5, 7, 9 }) },
                      {}, frame);

  const RunResult run = runSliceMesh(quoted((folder / "CT").string()) + " " + quoted((folder / "mesh.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err;
  EXPECT_TRUE(hasLine(run.err, "holds a structure set, RS.dcm: its ROIs are meshed, stacked on the folder's image series"))
    << run.err;
  EXPECT_FALSE(hasLine(run.err, "Frame of Reference")) << run.err; // the plan's own CT
  EXPECT_FALSE(hasLine(run.err, "not on the slices")) << run.err;
  EXPECT_TRUE(hasLine(run.err, "one slice missing, tiled across it")) << run.err;
  const MeshValidation v = expectValid(folder / "mesh.vtp");
  EXPECT_EQ(v.components, 1u);
  const double expected = polygonArea(r) * 10 * Spacing; // half a slice beyond each end contour
  EXPECT_NEAR(v.volume, expected, 0.02 * expected);

  // A structure set of another Frame of Reference (drawn on another scan, or not registered to this
  // one): still meshed where it says, with a warning naming both frames.
  const fs::path other = freshFolder("StructureSetOtherFrame");
  writeRTStructureSet((other / "RS.dcm").string(), { obliqueCylinder(1, "Oblique", centre, r, { 0, 1, 3, 5, 7, 9 }) }, {},
                      "1.2.826.0.1.3680043.2.1125.9.9");
  const RunResult elsewhere = runSliceMesh("--inputContours " + quoted((other / "RS.dcm").string()) + " " +
                                           quoted((folder / "CT").string()) + " " + quoted((other / "mesh.vtp").string()));
  ASSERT_EQ(elsewhere.exitCode, cli::Success) << elsewhere.err;
  EXPECT_TRUE(hasLine(elsewhere.err, std::string("names Frame of Reference 1.2.826.0.1.3680043.2.1125.9.9, '") +
                                       (folder / "CT").string() + "' is in " + frame))
    << elsewhere.err;
  EXPECT_NEAR(expectValid(other / "mesh.vtp").volume, v.volume, 1e-6 * v.volume);
  EXPECT_FALSE(hasLine(elsewhere.err, "lie between the slices")) << elsewhere.err;

  // Of the series' frame but drawn between its slices (on another phase or a rescan): said, with how
  // far (half a slice), and meshed where the structure set puts them.
  const fs::path between = freshFolder("StructureSetBetweenSlices");
  Vector3 shifted = centre;
  for (int k = 0; k < 3; ++k)
    shifted[k] += 0.5 * Spacing * f.normal[k];
  writeRTStructureSet((between / "RS.dcm").string(), { obliqueCylinder(1, "Oblique", shifted, r, { 0, 1, 3, 5, 7, 9 }) },
                      {}, frame);
  const RunResult off = runSliceMesh("--inputContours " + quoted((between / "RS.dcm").string()) + " " +
                                     quoted((folder / "CT").string()) + " " + quoted((between / "mesh.vtp").string()));
  ASSERT_EQ(off.exitCode, cli::Success) << off.err;
  EXPECT_TRUE(hasLine(off.err, "the contours of ROI 1 (Oblique) lie between the slices of '" + (folder / "CT").string() +
                                 "': up to " + std::to_string(0.5 * Spacing).substr(0, 3) + " mm from the nearest"))
    << off.err;
  EXPECT_NEAR(expectValid(between / "mesh.vtp").volume, v.volume, 0.01 * v.volume);

  // Two structure sets in the folder: which one is for the user to say. One line, nothing written.
  writeRTStructureSet((folder / "CT" / "RS2.dcm").string(), { obliqueCylinder(2, "Other", centre, r) });
  const RunResult two = runSliceMesh(quoted((folder / "CT").string()) + " " + quoted((folder / "none.vtp").string()));
  EXPECT_EQ(two.exitCode, cli::UnreadableInput) << two.err;
  ASSERT_EQ(linesOf(two.err).size(), 1u) << two.err;
  EXPECT_NE(two.err.find("holds 2 structure sets (RS.dcm, RS2.dcm): give the one to mesh with --inputContours"),
            std::string::npos)
    << two.err;
  EXPECT_FALSE(fs::exists(folder / "none.vtp"));
}

TEST(StructureSet, AnImageWhoseSlicesTheContoursAreNotOnGivesOneWarningAndTheContoursAreFollowed)
{
  const ObliqueFrame f;
  const fs::path folder = freshFolder("StructureSetOtherImage");
  writeRTStructureSet((folder / "RS.dcm").string(), { obliqueCylinder(1, "First", { -20.0, 40.0, 60.0 }, 10.0),
                                                      obliqueCylinder(2, "Second", { 30.0, 40.0, 60.0 }, 10.0) });
  writeReferenceImage(folder / "axial.nrrd", { Vector3{ 1, 0, 0 }, Vector3{ 0, 1, 0 }, Vector3{ 0, 0, 1 } },
                      { 1.0, 1.0, 2.0 });
  const RunResult run = runSliceMesh("--inputContours " + quoted((folder / "RS.dcm").string()) + " " +
                                     quoted((folder / "axial.nrrd").string()) + " " + quoted((folder / "mesh.vtp").string()));
  ASSERT_EQ(run.exitCode, cli::Success) << run.err;
  std::size_t warnings = 0;
  for (const std::string& line : linesOf(run.err))
    if (line.find("are not on the slices of") != std::string::npos)
    {
      ++warnings;
      EXPECT_EQ(line.rfind("SliceMesh: warning: the contours of ROI 1 (First), 2 (Second)", 0), 0u) << line;
      EXPECT_NE(line.find("axial.nrrd"), std::string::npos) << line;
    }
  EXPECT_EQ(warnings, 1u) << "one line for the set: " << run.err;
  // Followed along their own normal and spacing, the cylinders are whole (3 mm slices, not 2).
  const MeshValidation v = expectValid(folder / "mesh.vtp");
  EXPECT_EQ(v.components, 2u);
  const double expected = 2.0 * polygonArea(10.0) * 10 * Spacing;
  EXPECT_NEAR(v.volume, expected, 0.02 * expected);

  // An image that cannot be read: one line, nothing written.
  const RunResult missing = runSliceMesh("--inputContours " + quoted((folder / "RS.dcm").string()) + " " +
                                         quoted((folder / "missing.nrrd").string()) + " " +
                                         quoted((folder / "none.vtp").string()));
  EXPECT_EQ(missing.exitCode, cli::UnreadableInput) << missing.err;
  EXPECT_EQ(linesOf(missing.err).size(), 1u) << missing.err;
  EXPECT_FALSE(fs::exists(folder / "none.vtp"));
}

TEST(StructureSet, JsonContoursThroughInputContoursWithTheVolumeLeftOutAndReturnParameters)
{
  const fs::path folder = freshFolder("StructureSetJson");
  std::ofstream json(folder / "box.json");
  json << "{ \"rois\": [ { \"number\": 12, \"name\": \"Box\", \"color\": [1, 2, 3], \"slices\": [";
  for (int k = 0; k < 6; ++k)
    json << (k ? "," : "") << "{ \"z\": " << 2.0 * k << ", \"polygons\": [ [[0,0],[20,0],[20,10],[0,10]] ] }";
  json << "] } ] }";
  json.close();
  const RunResult r = runSliceMesh("--inputContours " + quoted((folder / "box.json").string()) +
                                   " --returnparameterfile " + quoted((folder / "results.txt").string()) + " " +
                                   quoted((folder / "box.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  const MeshValidation v = expectValid(folder / "box.vtp");
  EXPECT_NEAR(v.volume, 200.0 * 12.0, 0.03 * 2400.0);
  bool written = false, volume = false;
  for (const auto& [name, value] : returnParameters(folder / "results.txt"))
  {
    written = written || (name == "structuresWritten" && value == "1");
    volume = volume || (name == "volume" && std::abs(std::stod(value) - v.volume) < 1e-3 * v.volume);
  }
  EXPECT_TRUE(written);
  EXPECT_TRUE(volume);
}

} // namespace
} // namespace slicemesh::testing

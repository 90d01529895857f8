// Segmentation files as input of the executable: 3D Slicer .seg.nrrd files with overlapping
// segments, a two-layer binary one and a fractional one (on a mirrored grid), and DICOM SEGs, binary
// and fractional (on an oblique grid), all written here from analytic shapes. Each segment becomes
// its own closed, manifold, self-intersection-free mesh, named and coloured from the file, of the
// shape's volume and centred where the shape is; bad files are refused in one line with nothing
// written.
#include "CLITestSupport.h"
#include "DicomSeriesWriter.h"
#include "ExitCodes.h"
#include "MeshReader.h"
#include "Measures/MeshValidation.h"
#include "SegmentationFileWriters.h"

#include <gtest/gtest.h>


#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

/** A written .vtp: its triangles, per-triangle labels and colours, and the structures' names. */
struct WrittenModel
{
  TriangleMesh mesh;
  std::vector<int> labels;
  std::vector<std::array<int, 3>> colors;
  std::vector<std::string> names;
};

WrittenModel readModel(const fs::path& path)
{
  const MeshFile file = readMesh(path.string());
  WrittenModel model;
  model.mesh = file.mesh;
  model.labels = file.attributes.cellLabels;
  for (const auto& rgb : file.attributes.cellColors)
    model.colors.push_back({ rgb[0], rgb[1], rgb[2] });
  for (const MeshAttributes::Structure& structure : file.attributes.structures)
    model.names.push_back(structure.name);
  return model;
}

/** The centre of mass of the solid a closed, outward mesh encloses. */
PhysicalPoint centroid(const TriangleMesh& mesh)
{
  double volume = 0.0;
  PhysicalPoint sum{ 0, 0, 0 };
  for (const auto& t : mesh.triangles)
  {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const double v = (a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x)) / 6.0;
    volume += v;
    sum[0] += v * (a.x + b.x + c.x) / 4.0;
    sum[1] += v * (a.y + b.y + c.y) / 4.0;
    sum[2] += v * (a.z + b.z + c.z) / 4.0;
  }
  return { sum[0] / volume, sum[1] / volume, sum[2] / volume };
}

double distance(const PhysicalPoint& a, const PhysicalPoint& b)
{
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Tolerances. Volume: the shapes are traced from their voxels, and the sub-voxel contours of a
// convex shape lie a little inside its voxels' outline. Measured: the balls of radius 7, 6 and 5 mm
// on voxels of 0.7 to 1.5 mm come out 1.6%, 2.2% and 3.8% small, the box 2.6% (against its voxels:
// its edges and corners are rounded), the ellipsoid whose short semi-axes are 4 mm (3 to 4.5 voxels)
// 4.5%: 5% for the first, 6% for the ellipsoid. Centroid: measured 0.01 to 0.13 mm from the true
// centre; within 0.25 mm (a sixth of the largest voxel side).
constexpr double roundVolumeTolerance = 0.05, thinVolumeTolerance = 0.06, centreTolerance = 0.25;

/** What one segment's mesh must be: closed, manifold, no self-intersections, of `volume` within
 *  `volumeTolerance` (relative), centred within centreTolerance of `centre`, in one colour. */
struct ExpectedSegment
{
  std::string file;
  std::string name;
  std::array<int, 3> rgb;
  double volume;
  PhysicalPoint centre;
  double volumeTolerance = roundVolumeTolerance;
};

void expectSegmentMesh(const fs::path& path, const ExpectedSegment& expected)
{
  SCOPED_TRACE(expected.file);
  ASSERT_TRUE(fs::exists(path));
  const WrittenModel model = readModel(path);
  const MeshValidation v = validateMesh(model.mesh);
  EXPECT_TRUE(v.closed());
  EXPECT_TRUE(v.manifold());
  EXPECT_TRUE(v.selfIntersectionChecked);
  EXPECT_EQ(v.selfIntersections, 0u);
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, 1u);
  EXPECT_NEAR(v.volume, expected.volume, expected.volumeTolerance * expected.volume) << v.summary();
  const PhysicalPoint c = centroid(model.mesh);
  EXPECT_LT(distance(c, expected.centre), centreTolerance)
    << "centroid " << c[0] << " " << c[1] << " " << c[2] << ", expected " << expected.centre[0] << " "
    << expected.centre[1] << " " << expected.centre[2];
  ASSERT_EQ(model.names.size(), 1u);
  EXPECT_EQ(model.names.front(), expected.name);
  ASSERT_EQ(model.colors.size(), model.mesh.triangles.size());
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(model.colors.front()[ch], expected.rgb[ch], 1) << "channel " << ch;
}

/** 3D Slicer's file of the tests: a mirrored 40 x 36 x 30 grid of 0.8 x 0.9 x 1.5 mm voxels; layer 0
 *  holds a ball (value 1) and a box (value 2), layer 1 a smaller ball overlapping the first (value
 *  1); a fourth segment (layer 1, value 2) has no voxel. */
constexpr double ballRadius = 7.0, lesionRadius = 5.0;
const PhysicalPoint ballCentre{ 14.0, 3.0, 24.0 }, lesionCentre{ 19.0, 3.0, 26.0 };

ImageGrid slicerGrid()
{
  ImageGrid grid;
  grid.size = { 40, 36, 30 };
  grid.spacing = { 0.8, 0.9, 1.5 };
  grid.origin = { 30.0, -12.0, 4.0 };
  grid.axes = { { { -1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  return grid;
}

bool inBox(const PhysicalPoint& p)
{
  return p[0] >= 2.0 && p[0] <= 8.0 && p[1] >= 10.0 && p[1] <= 17.0 && p[2] >= 10.0 && p[2] <= 20.0;
}

/** Written gzip-compressed, as Slicer writes by default. */
fs::path slicerFile(const fs::path& folder)
{
  const fs::path path = folder / "structures.seg.nrrd";
  writeSlicerSegmentation(
    path, slicerGrid(),
    { [](const PhysicalPoint& p) -> unsigned char { return distance(p, ballCentre) <= ballRadius ? 1 : inBox(p) ? 2 : 0; },
      [](const PhysicalPoint& p) -> unsigned char { return distance(p, lesionCentre) <= lesionRadius ? 1 : 0; } },
    { { "Segment_1", "Ball", "0.9 0.2 0.1", "0", "1" },
      { "Segment_2", "Box", "0.2 0.4 0.9", "0", "2" },
      { "Segment_3", "Lesion", "1 0.85 0", "1", "1" },
      { "Segment_4", "Empty", "0.5 0.5 0.5", "1", "2" } },
    {}, true);
  return path;
}

/** The box's voxels (centres inside [2, 8] x [10, 17] x [10, 20] mm): their volume, and the centre
 *  of the block they make. */
std::pair<double, PhysicalPoint> boxVoxels()
{
  const ImageGrid grid = slicerGrid();
  std::size_t voxels = 0;
  PhysicalPoint sum{ 0, 0, 0 };
  for (int k = 0; k < grid.size[2]; ++k)
    for (int j = 0; j < grid.size[1]; ++j)
      for (int i = 0; i < grid.size[0]; ++i)
        if (const PhysicalPoint p = grid.point(i, j, k); inBox(p))
        {
          ++voxels;
          for (int a = 0; a < 3; ++a)
            sum[a] += p[a];
        }
  return { static_cast<double>(voxels) * grid.spacing[0] * grid.spacing[1] * grid.spacing[2],
           { sum[0] / voxels, sum[1] / voxels, sum[2] / voxels } };
}

double boxVolume()
{
  return boxVoxels().first;
}

double ballVolume(double radius)
{
  return 4.0 / 3.0 * M_PI * radius * radius * radius;
}

TEST(SegmentationFileInput, AnEmptySegmentAskedForIsSaidToBeEmpty)
{
  // --label 4, the file's empty segment: "every label ... is smaller than the minimum component
  // volume 0 mm^3", which named an option nobody set.
  const fs::path folder = freshFolder("segfile-empty-asked");
  const fs::path input = slicerFile(folder);
  const RunResult r = runSliceMesh("--label 4 " + quoted(input.string()) + " " + quoted((folder / "empty.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::EmptySegmentation) << r.err;
  EXPECT_NE(r.err.find("the segment asked for, 4 (Empty), holds no voxel"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder / "empty.vtp"));
}

TEST(SegmentationFileInput, SlicerTwoLayersGiveOneNamedColouredMeshPerSegment)
{
  const fs::path folder = freshFolder("segfile-slicer");
  const fs::path input = slicerFile(folder);
  const fs::path meshes = folder / "meshes";
  const RunResult r = runSliceMesh("--outputDirectory " + quoted(meshes.string()) + " " + quoted(input.string()) + " " +
                                   quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.err.find("SliceMesh: warning: segment 4 (Empty) is empty; no mesh"), std::string::npos) << r.err;

  const std::vector<ExpectedSegment> expected{
    { "001_Ball.vtp", "Ball", { 230, 51, 26 }, ballVolume(ballRadius), ballCentre },
    { "002_Box.vtp", "Box", { 51, 102, 230 }, boxVolume(), boxVoxels().second },
    { "003_Lesion.vtp", "Lesion", { 255, 217, 0 }, ballVolume(lesionRadius), lesionCentre },
  };
  for (const ExpectedSegment& e : expected)
    expectSegmentMesh(meshes / e.file, e);
  EXPECT_FALSE(fs::exists(meshes / "004_Empty.vtp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(meshes), fs::directory_iterator()), 3);

  // The merged model: the three meshes, each triangle with its segment's number and colour.
  const WrittenModel all = readModel(folder / "all.vtp");
  EXPECT_EQ(all.names, (std::vector<std::string>{ "Ball", "Box", "Lesion" }));
  ASSERT_EQ(all.labels.size(), all.mesh.triangles.size());
  std::map<int, std::set<std::array<int, 3>>> colorsByLabel;
  for (std::size_t n = 0; n < all.labels.size(); ++n)
    colorsByLabel[all.labels[n]].insert(all.colors[n]);
  ASSERT_EQ(colorsByLabel.size(), 3u);
  for (int label = 1; label <= 3; ++label)
  {
    ASSERT_EQ(colorsByLabel[label].size(), 1u) << label;
    const std::array<int, 3> rgb = *colorsByLabel[label].begin();
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(rgb[ch], expected[label - 1].rgb[ch], 1) << label;
  }
  // The overlap is meshed twice, once in each segment: the volumes add up to more than the union.
  EXPECT_NEAR(validateMeshTopology(all.mesh).volume,
              ballVolume(ballRadius) + boxVolume() + ballVolume(lesionRadius),
              roundVolumeTolerance * (ballVolume(ballRadius) + boxVolume() + ballVolume(lesionRadius)));
}

TEST(SegmentationFileInput, AVeryLongSegmentNameGivesAFileNameThatCanBeWritten)
{
  // A file name holds at most 255 bytes: a segment named with 300 characters failed the whole run
  // (exit 6, the merged model not written) after the other segments' files were.
  const fs::path folder = freshFolder("segfile-longname");
  const fs::path input = folder / "long.seg.nrrd";
  const std::string longName(300, 'A');
  writeSlicerSegmentation(
    input, slicerGrid(),
    { [](const PhysicalPoint& p) -> unsigned char { return distance(p, ballCentre) <= ballRadius ? 1 : inBox(p) ? 2 : 0; } },
    { { "Segment_1", longName, "0.9 0.2 0.1", "0", "1" }, { "Segment_2", "Box", "0.2 0.4 0.9", "0", "2" } }, {}, false);
  const fs::path meshes = folder / "meshes";
  const RunResult r = runSliceMesh("--outputDirectory " + quoted(meshes.string()) + " " + quoted(input.string()) + " " +
                                   quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  const fs::path cut = meshes / ("001_" + std::string(200, 'A') + ".vtp");
  expectSegmentMesh(cut, { cut.filename().string(), longName, { 230, 51, 26 }, ballVolume(ballRadius), ballCentre });
  EXPECT_TRUE(fs::exists(meshes / "002_Box.vtp"));
  EXPECT_TRUE(fs::exists(folder / "all.vtp"));
}

TEST(SegmentationFileInput, LabelsPickSegmentsByNumberOrName)
{
  const fs::path folder = freshFolder("segfile-pick");
  const fs::path input = slicerFile(folder);
  const fs::path meshes = folder / "meshes";
  const RunResult r = runSliceMesh("--labels 3 --outputDirectory " + quoted(meshes.string()) + " " +
                                   quoted(input.string()) + " " + quoted((folder / "lesion.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_TRUE(fs::exists(meshes / "003_Lesion.vtp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(meshes), fs::directory_iterator()), 1);
  expectSegmentMesh(folder / "lesion.vtp", { "lesion.vtp", "Lesion", { 255, 217, 0 }, ballVolume(lesionRadius), lesionCentre });

  // By name, in any case, mixed with numbers.
  const fs::path named = folder / "named";
  const RunResult byName = runSliceMesh("--labels BOX,3 --outputDirectory " + quoted(named.string()) + " " +
                                        quoted(input.string()) + " " + quoted((folder / "named.vtp").string()));
  ASSERT_EQ(byName.exitCode, cli::Success) << byName.err;
  EXPECT_TRUE(fs::exists(named / "002_Box.vtp"));
  EXPECT_TRUE(fs::exists(named / "003_Lesion.vtp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(named), fs::directory_iterator()), 2);
  const RunResult unknown = runSliceMesh("--labels Tumour " + quoted(input.string()) + " " + quoted((folder / "none.vtp").string()));
  EXPECT_EQ(unknown.exitCode, cli::EmptySegmentation) << unknown.err;
  EXPECT_NE(unknown.err.find("no segment named 'Tumour' (its segments: 1 Ball, 2 Box, 3 Lesion, 4 Empty)"), std::string::npos)
    << unknown.err;

  // A number the file does not have: exit 4, the message lists the segments, nothing written.
  const RunResult missing = runSliceMesh("--labels 7 " + quoted(input.string()) + " " + quoted((folder / "none.vtp").string()));
  EXPECT_EQ(missing.exitCode, cli::EmptySegmentation) << missing.err;
  EXPECT_EQ(linesOf(missing.err).size(), 1u) << missing.err;
  EXPECT_NE(missing.err.find("no segment numbered 7 (its segments: 1 Ball, 2 Box, 3 Lesion, 4 Empty)"), std::string::npos)
    << missing.err;
  EXPECT_FALSE(fs::exists(folder / "none.vtp"));
}

/** The index of the voxel centred at p on the grid. */
std::array<int, 3> indexOf(const ImageGrid& grid, const PhysicalPoint& p)
{
  std::array<int, 3> index{};
  for (int axis = 0; axis < 3; ++axis)
  {
    double t = 0;
    for (int a = 0; a < 3; ++a)
      t += (p[a] - grid.origin[a]) * grid.axes[axis][a];
    index[axis] = static_cast<int>(std::lround(t / grid.spacing[axis]));
  }
  return index;
}

/** A fractional .seg.nrrd as 3D Slicer writes one, on the grid of slicerFile: a sphere (radius 7 mm)
 *  and a smaller one overlapping it (radius 5 mm), each voxel's value counted from 216 samples of
 *  the analytic ball (-108 empty to 108 full), each segment in its layer and cropped to its extent
 *  (the box of its partly filled voxels and one more, as Slicer pads a fractional labelmap) with 0
 *  around it (Slicer's padding to the file's box); a third segment is empty (all 0, an empty extent). */
fs::path slicerFractionalFile(const fs::path& folder, const std::string& name)
{
  const ImageGrid grid = slicerGrid();
  auto ball = [](const PhysicalPoint& centre, double radius)
  { return [=](const PhysicalPoint& p) { return distance(p, centre) <= radius; }; };
  const std::function<bool(const PhysicalPoint&)> shapes[2] = { ball(ballCentre, ballRadius), ball(lesionCentre, lesionRadius) };
  std::array<std::array<int, 6>, 2> extents;
  for (int s = 0; s < 2; ++s)
  {
    extents[s] = { grid.size[0], -1, grid.size[1], -1, grid.size[2], -1 };
    for (int k = 0; k < grid.size[2]; ++k)
      for (int j = 0; j < grid.size[1]; ++j)
        for (int i = 0; i < grid.size[0]; ++i)
          if (slicerFraction(grid, grid.point(i, j, k), shapes[s]) > -108)
          {
            const std::array<int, 3> index{ i, j, k };
            for (int a = 0; a < 3; ++a)
            {
              extents[s][2 * a] = std::min(extents[s][2 * a], std::max(index[a] - 1, 0));
              extents[s][2 * a + 1] = std::max(extents[s][2 * a + 1], std::min(index[a] + 1, grid.size[a] - 1));
            }
          }
  }
  auto layer = [&](int s)
  {
    return [=](const PhysicalPoint& p)
    {
      const std::array<int, 3> index = indexOf(grid, p);
      for (int a = 0; a < 3; ++a)
        if (index[a] < extents[s][2 * a] || index[a] > extents[s][2 * a + 1])
          return 0;
      return slicerFraction(grid, p, shapes[s]);
    };
  };
  auto text = [](const std::array<int, 6>& e)
  {
    std::ostringstream out;
    out << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4] << " " << e[5];
    return out.str();
  };
  const fs::path path = folder / name;
  writeSlicerFractionalSegmentation(path, grid, { layer(0), layer(1), [](const PhysicalPoint&) { return 0; } },
                                    { { "Segment_1", "Sphere", "0.9 0.2 0.1", "0", "1", text(extents[0]) },
                                      { "Segment_2", "Lesion", "1 0.85 0", "1", "1", text(extents[1]) },
                                      { "Segment_3", "Empty", "0.5 0.5 0.5", "2", "1", "0 -1 0 -1 0 -1" } },
                                    {}, true);
  return path;
}

TEST(SegmentationFileInput, SlicerFractionalGivesOneNamedColouredMeshPerSegmentAtHalf)
{
  const fs::path folder = freshFolder("segfile-slicer-fractional");
  const fs::path input = slicerFractionalFile(folder, "fractional.seg.nrrd");
  const fs::path meshes = folder / "meshes";
  const RunResult r = runSliceMesh("--outputDirectory " + quoted(meshes.string()) + " " + quoted(input.string()) + " " +
                                   quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.err.find("SliceMesh: warning: segment 3 (Empty) is empty; no mesh"), std::string::npos) << r.err;
  // The voxels at least half inside trace the balls as a binary file's voxels (centres inside) do.
  // Measured: the spheres of radius 7 and 5 mm come out 0.55% and 1.6% small (the binary file's 0.10%
  // and 1.2%), their centres 0.05 and 0.10 mm off: within 3%, and the 0.25 mm of the others. The 0
  // padding around each segment's extent (half full) would add a box to it if it were read as inside.
  constexpr double fractionalVolumeTolerance = 0.03;
  expectSegmentMesh(meshes / "001_Sphere.vtp", { "001_Sphere.vtp", "Sphere", { 230, 51, 26 }, ballVolume(ballRadius),
                                                 ballCentre, fractionalVolumeTolerance });
  expectSegmentMesh(meshes / "002_Lesion.vtp", { "002_Lesion.vtp", "Lesion", { 255, 217, 0 }, ballVolume(lesionRadius),
                                                 lesionCentre, fractionalVolumeTolerance });
  EXPECT_FALSE(fs::exists(meshes / "003_Empty.vtp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(meshes), fs::directory_iterator()), 2);
  const WrittenModel all = readModel(folder / "all.vtp");
  EXPECT_EQ(all.names, (std::vector<std::string>{ "Sphere", "Lesion" }));
}

/** The DICOM SEGs of the tests: an oblique 41 x 37 x 24 grid of 0.7 x 0.9 x 1.25 mm pixels (1517
 *  pixels a frame, so most frames of the binary file start mid-byte); a ball of radius 6 mm and an
 *  ellipsoid (semi-axes 8, 4, 4 mm along L, P, S) overlapping it. */
ImageGrid dicomGrid()
{
  ImageGrid grid;
  grid.size = { 41, 37, 24 };
  grid.spacing = { 0.7, 0.9, 1.25 };
  grid.origin = { -20.0, 15.0, -40.0 };
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6), ct = std::cos(M_PI / 9), st = std::sin(M_PI / 9);
  grid.axes = { { { c, s, 0 }, { -s * ct, c * ct, st }, { s * st, -c * st, ct } } };
  return grid;
}

const PhysicalPoint sphereCentre = dicomGrid().point(20, 18, 12);
const PhysicalPoint ellipsoidCentre{ sphereCentre[0] + 5.0, sphereCentre[1] + 1.0, sphereCentre[2] - 1.0 };

fs::path dicomFile(const fs::path& folder, const std::string& name, unsigned int maxFraction)
{
  const fs::path path = folder / name;
  // The sphere's fraction falls from 1 to 0 over 0.8 mm across its surface (half at the surface);
  // the ellipsoid's is 0 or 1.
  writeDicomSegmentation(path, dicomGrid(),
                         { { "Sphere", { 0.2, 0.6, 0.9 },
                             [](const PhysicalPoint& p) { return 0.5 - (distance(p, sphereCentre) - 6.0) / 0.8; } },
                           { "Ellipsoid", { 0.9, 0.5, 0.1 },
                             [](const PhysicalPoint& p)
                             {
                               const double x = (p[0] - ellipsoidCentre[0]) / 8.0, y = (p[1] - ellipsoidCentre[1]) / 4.0,
                                            z = (p[2] - ellipsoidCentre[2]) / 4.0;
                               return x * x + y * y + z * z <= 1.0 ? 1.0 : 0.0;
                             } } },
                         maxFraction);
  return path;
}

void expectDicomMeshes(const fs::path& meshes, bool ras)
{
  auto inSystem = [&](PhysicalPoint p)
  {
    if (ras)
      p[0] = -p[0], p[1] = -p[1];
    return p;
  };
  expectSegmentMesh(meshes / "001_Sphere.vtp",
                    { "001_Sphere.vtp", "Sphere", { 51, 153, 230 }, ballVolume(6.0), inSystem(sphereCentre) });
  expectSegmentMesh(meshes / "002_Ellipsoid.vtp", { "002_Ellipsoid.vtp", "Ellipsoid", { 230, 128, 26 },
                                                    4.0 / 3.0 * M_PI * 8 * 4 * 4, inSystem(ellipsoidCentre),
                                                    thinVolumeTolerance });
}

TEST(SegmentationFileInput, DicomSegBinaryOnAnObliqueGridLandsWhereTheShapesAre)
{
  const fs::path folder = freshFolder("segfile-dicom-binary");
  const fs::path input = dicomFile(folder, "binary.dcm", 0);
  const RunResult r = runSliceMesh("--outputDirectory " + quoted((folder / "meshes").string()) + " " +
                                   quoted(input.string()) + " " + quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  expectDicomMeshes(folder / "meshes", false);
}

TEST(SegmentationFileInput, DicomSegFractionalInRasLandsWhereTheShapesAre)
{
  const fs::path folder = freshFolder("segfile-dicom-fractional");
  const fs::path input = dicomFile(folder, "fractional.dcm", 255);
  const RunResult r = runSliceMesh("--coordinateSystem RAS --outputDirectory " + quoted((folder / "meshes").string()) +
                                   " " + quoted(input.string()) + " " + quoted((folder / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  expectDicomMeshes(folder / "meshes", true);
}

TEST(SegmentationFileInput, AFolderOfAnImageSeriesAndItsSegmentationMeshesTheSegments)
{
  // An export of the CT slices and the SEG drawn on them, given as a folder: the series was read and
  // thresholded, the segmentation passed over without a word. Its segments are meshed now, as a
  // structure set beside its series is.
  const fs::path folder = freshFolder("segfile-dicom-folder") / "export";
  fs::create_directories(folder);
  const ImageGrid grid = dicomGrid();
  auto ct = testing::CTVolume::New();
  ct->SetRegions({ { 0, 0, 0 }, { std::size_t(grid.size[0]), std::size_t(grid.size[1]), std::size_t(grid.size[2]) } });
  ct->Allocate();
  ct->FillBuffer(40);
  testing::CTVolume::SpacingType spacing;
  testing::CTVolume::PointType origin;
  testing::CTVolume::DirectionType direction;
  for (int row = 0; row < 3; ++row)
  {
    spacing[row] = grid.spacing[row];
    origin[row] = grid.origin[row];
    for (int axis = 0; axis < 3; ++axis)
      direction[row][axis] = grid.axes[axis][row];
  }
  ct->SetSpacing(spacing);
  ct->SetOrigin(origin);
  ct->SetDirection(direction);
  testing::writeCTSeries(ct, folder);
  dicomFile(folder, "SEG.dcm", 0);
  const RunResult r = runSliceMesh("--outputDirectory " + quoted((folder.parent_path() / "meshes").string()) + " " +
                                   quoted(folder.string()) + " " + quoted((folder.parent_path() / "all.vtp").string()));
  ASSERT_EQ(r.exitCode, cli::Success) << r.err;
  EXPECT_NE(r.err.find("holds a segmentation, SEG.dcm: its segments are meshed"), std::string::npos) << r.err;
  expectDicomMeshes(folder.parent_path() / "meshes", false);
  // Two segmentations: which one is for the user to say.
  fs::copy_file(folder / "SEG.dcm", folder / "SEG2.dcm");
  const RunResult two = runSliceMesh(quoted(folder.string()) + " " + quoted((folder.parent_path() / "two.vtp").string()));
  EXPECT_EQ(two.exitCode, cli::UnreadableInput) << two.err;
  EXPECT_NE(two.err.find("holds 2 segmentations (SEG.dcm, SEG2.dcm)"), std::string::npos) << two.err;
}

/** A bad input: exit `code`, one line on stderr naming the file, nothing written. */
void expectRefused(const fs::path& folder, const fs::path& input, cli::ExitCode code, const std::string& words)
{
  SCOPED_TRACE(input.filename().string());
  const fs::path meshes = folder / ("meshes-" + input.filename().string());
  const fs::path output = folder / ("out-" + input.filename().string() + ".vtp");
  const RunResult r = runSliceMesh("--outputDirectory " + quoted(meshes.string()) + " " + quoted(input.string()) + " " +
                                   quoted(output.string()));
  EXPECT_EQ(r.exitCode, code) << r.err;
  ASSERT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("SliceMesh: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(input.filename().string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_TRUE(!fs::exists(meshes) || fs::is_empty(meshes));
}

TEST(SegmentationFileInput, BadFilesAreRefusedInOneLineAndNothingIsWritten)
{
  const fs::path folder = freshFolder("segfile-bad");
  const fs::path slicer = slicerFile(folder);
  const fs::path cutSlicer = folder / "cut.seg.nrrd";
  fs::copy_file(slicer, cutSlicer);
  fs::resize_file(cutSlicer, fs::file_size(slicer) / 2);
  expectRefused(folder, cutSlicer, cli::UnreadableInput, "(a truncated or damaged file?)");

  const fs::path dicom = dicomFile(folder, "seg.dcm", 0);
  const fs::path cutDicom = folder / "cut.dcm";
  fs::copy_file(dicom, cutDicom);
  fs::resize_file(cutDicom, fs::file_size(dicom) - 500);
  expectRefused(folder, cutDicom, cli::UnreadableInput, "(a truncated or damaged file?)");

  // Fields that contradict the image: a layer the file does not have.
  const fs::path badLayer = folder / "bad-layer.seg.nrrd";
  writeSlicerSegmentation(badLayer, slicerGrid(), { [](const PhysicalPoint&) -> unsigned char { return 1; } },
                          { { "Segment_1", "Ball", "1 0 0", "3", "1" } });
  expectRefused(folder, badLayer, cli::UnreadableInput, "Segment0_Layer is 3");

  // Fractional files whose layout cannot be read: two segments in one layer, fractions of an
  // unknown scale (unsigned char without a range), a fraction outside Slicer's -108..108.
  const fs::path shared = folder / "shared.seg.nrrd";
  writeSlicerFractionalSegmentation(shared, slicerGrid(), { [](const PhysicalPoint&) { return 108; } },
                                    { { "Segment_1", "Ball", "1 0 0", "0", "1" }, { "Segment_2", "Box", "0 1 0", "0", "1" } });
  expectRefused(folder, shared, cli::UnreadableInput, "a fractional labelmap has a layer of its own for each segment");
  const fs::path unsigned8 = folder / "unsigned.seg.nrrd";
  writeSlicerFractionalSegmentation(unsigned8, slicerGrid(), { [](const PhysicalPoint&) { return 200; } },
                                    { { "Segment_1", "Ball", "1 0 0", "0", "1" } }, {}, false, "unsigned char");
  expectRefused(folder, unsigned8, cli::UnreadableInput, "a fractional labelmap of unsigned char voxels without");
  const fs::path over = folder / "over.seg.nrrd";
  writeSlicerFractionalSegmentation(over, slicerGrid(), { [](const PhysicalPoint& p) { return p[2] > 20.0 ? 127 : -108; } },
                                    { { "Segment_1", "Ball", "1 0 0", "0", "1" } }, {}, true);
  expectRefused(folder, over, cli::UnreadableInput, "is 127, outside the fractional range -108 to 108");

  // Every segment empty: nothing to mesh.
  const fs::path empty = folder / "empty.seg.nrrd";
  writeSlicerSegmentation(empty, slicerGrid(), { [](const PhysicalPoint&) -> unsigned char { return 0; } },
                          { { "Segment_1", "Ball", "1 0 0", "0", "1" } });
  const RunResult r = runSliceMesh(quoted(empty.string()) + " " + quoted((folder / "empty.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::EmptySegmentation) << r.err;
  EXPECT_NE(r.err.find("every segment of the 3D Slicer segmentation is empty"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder / "empty.vtp"));
}

} // namespace
} // namespace slicemesh::testing

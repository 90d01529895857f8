// Writes the StructureFuzzer's seeds into a folder: one small file of each kind the command line
// reads as structures - an RT Structure Set (with a hole, a keyhole and a POINT item), SliceMesh's
// JSON contours, 3D Slicer's planar contours as legacy and XML VTK polydata, a two-layer .seg.nrrd,
// a fractional one and a binary DICOM SEG - so that the fuzzer starts inside each reader rather than
// at its magic; and a structure set with a damaged length, a past finding.
//   MakeStructureFuzzSeeds <folder>
#include "SegmentationFileWriters.h"
#include "StructureSetWriter.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{

using namespace slicemesh;
namespace fs = std::filesystem;

Polygon3 square(double cx, double cy, double z, double half)
{
  return { { cx - half, cy - half, z }, { cx + half, cy - half, z }, { cx + half, cy + half, z }, { cx - half, cy + half, z } };
}

void writeStructureSet(const fs::path& path)
{
  PlanarStructure ring;
  ring.number = 1;
  ring.name = "Ring";
  ring.rgb = { 200, 40, 40 };
  PlanarStructure keyhole;
  keyhole.number = 2;
  keyhole.name = "Keyhole";
  for (int k = 0; k < 3; ++k)
  {
    ring.contours.push_back(square(0.0, 0.0, 2.0 * k, 6.0));
    ring.contours.push_back(square(0.0, 0.0, 2.0 * k, 2.0));
    keyhole.contours.push_back({ { 20, 0, 2.0 * k }, { 26, 0, 2.0 * k }, { 26, 6, 2.0 * k }, { 20, 6, 2.0 * k },
                                 { 20, 3, 2.0 * k }, { 22, 3, 2.0 * k }, { 22, 4, 2.0 * k }, { 24, 4, 2.0 * k },
                                 { 24, 2, 2.0 * k }, { 22, 2, 2.0 * k }, { 22, 3, 2.0 * k }, { 20, 3, 2.0 * k } });
  }
  writeRTStructureSet(path.string(), { ring, keyhole }, { { 2, "POINT", { { 23, 3, 0 } } } });
}

/** The structure set with its meta header's first element claiming about 4 GB: DCMTK allocated such
 *  a value before finding the file too short (an out-of-memory the fuzzer found), so every run
 *  starts from it. */
void writeStructureSetWithDamagedLength(const fs::path& whole, const fs::path& path)
{
  std::ifstream in(whole, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string version("\x02\x00\x01\x00OB\x00\x00\x02\x00\x00\x00", 12);
  const std::size_t at = bytes.find(version);
  if (at != std::string::npos)
    bytes.replace(at + 10, 2, "\xff\xff");
  std::ofstream(path, std::ios::binary) << bytes;
}

/** Appends the value's bytes, most significant first, as the legacy binary format stores them. */
template <typename T>
void appendBigEndian(std::string& bytes, T value)
{
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  for (std::size_t i = sizeof(T); i-- > 0;)
    bytes += static_cast<char>(raw[i]);
}

/** Two square contours as legacy polydata of format 4 (ASCII and binary) and 5, and as XML. */
void writePolyData(const fs::path& folder)
{
  const int corners[8][3] = { { 0, 0, 0 }, { 4, 0, 0 }, { 4, 4, 0 }, { 0, 4, 0 }, { 0, 0, 2 }, { 4, 0, 2 }, { 4, 4, 2 }, { 0, 4, 2 } };
  const int cells[12] = { 5, 0, 1, 2, 3, 0, 5, 4, 5, 6, 7, 4 };
  std::ofstream(folder / "contours.vtk") << "# vtk DataFile Version 4.2\nRing SPACE=LPS\nASCII\nDATASET POLYDATA\nPOINTS 8 double\n"
                                            "0 0 0 4 0 0 4 4 0 0 4 0 0 0 2 4 0 2 4 4 2 0 4 2\nLINES 2 12\n5 0 1 2 3 0\n5 4 5 6 7 4\n";
  std::ofstream(folder / "contours-5.vtk") << "# vtk DataFile Version 5.1\nRing\nASCII\nDATASET POLYDATA\nFIELD FieldData 1\n"
                                              "LabelName 1 1 string\nLeft%20ring\n\nPOINTS 8 float\n"
                                              "0 0 0 4 0 0 4 4 0 0 4 0 0 0 2 4 0 2 4 4 2 0 4 2\nLINES 3 10\n"
                                              "OFFSETS vtktypeint64\n0 5 10\nCONNECTIVITY vtktypeint64\n0 1 2 3 0 4 5 6 7 4\n"
                                              "POINT_DATA 8\n";
  std::string binary = "# vtk DataFile Version 4.2\nRing\nBINARY\nDATASET POLYDATA\nFIELD FieldData 1\nLabelName 1 1 string\n";
  binary += static_cast<char>(0xC0 | 4); // a string of 4 bytes
  binary += "Ring\nPOINTS 8 float\n";
  for (const auto& corner : corners)
    for (const int c : corner)
      appendBigEndian(binary, static_cast<float>(c));
  binary += "\nLINES 2 12\n";
  for (const int value : cells)
    appendBigEndian(binary, static_cast<std::int32_t>(value));
  binary += "\n";
  std::ofstream(folder / "contours-binary.vtk", std::ios::binary) << binary;
  const fs::path xml = folder / "contours.vtp";
  std::ofstream(xml) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "<PolyData><Piece NumberOfPoints=\"8\" NumberOfVerts=\"0\" NumberOfLines=\"2\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                        "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
                        "0 0 0 4 0 0 4 4 0 0 4 0 0 0 2 4 0 2 4 4 2 0 4 2</DataArray></Points>\n"
                        "<Lines><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 0 4 5 6 7 4</DataArray>"
                        "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">5 10</DataArray></Lines>\n"
                        "</Piece></PolyData></VTKFile>\n";
}

void writeJson(const fs::path& path)
{
  std::ofstream(path) << "{ \"coordinateSystem\": \"LPS\", \"rois\": [ { \"number\": 3, \"name\": \"Box\", "
                         "\"color\": [10, 20, 30], \"slices\": [ { \"z\": 0, \"polygons\": [ [[0,0],[8,0],[8,4],[0,4]], "
                         "[[2,1],[3,1],[3,2]] ] }, { \"z\": 2.5, \"polygons\": [ [[0,0,2.5],[8,0,2.5],[8,4,2.5]] ] } ] } ] }\n";
}

void writeSegmentations(const fs::path& nrrd, const fs::path& fractional, const fs::path& dicom)
{
  testing::ImageGrid grid;
  grid.size = { 4, 3, 3 };
  grid.spacing = { 1.0, 1.0, 2.0 };
  auto ball = [](const testing::PhysicalPoint& p) { return std::hypot(p[0] - 1.5, p[1] - 1.0, p[2] - 2.0) < 1.6; };
  testing::writeSlicerSegmentation(
    nrrd, grid,
    { [&](const testing::PhysicalPoint& p) { return static_cast<unsigned char>(ball(p) ? 1 : 0); },
      [&](const testing::PhysicalPoint& p) { return static_cast<unsigned char>(p[0] > 1.0 ? 2 : 0); } },
    { { "Segment_1", "Ball", "1 0 0", "0", "1" }, { "Segment_2", "Slab", "0 0 1", "1", "2" } });
  testing::writeSlicerFractionalSegmentation(
    fractional, grid,
    { [&](const testing::PhysicalPoint& p) { return testing::slicerFraction(grid, p, ball); },
      [&](const testing::PhysicalPoint& p) { return p[0] > 1.0 ? 108 : 0; } },
    { { "Segment_1", "Ball", "1 0 0", "0", "1", "0 3 0 2 0 2" }, { "Segment_2", "Slab", "0 0 1", "1", "1", "1 3 0 2 0 1" } });
  testing::writeDicomSegmentation(dicom, grid,
                                  { { "Ball", { 1.0, 0.0, 0.0 }, [&](const testing::PhysicalPoint& p) { return ball(p) ? 1.0 : 0.0; } } });
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: MakeStructureFuzzSeeds <folder>" << std::endl;
    return 2;
  }
  const fs::path folder(argv[1]);
  fs::create_directories(folder);
  writeStructureSet(folder / "structure-set.dcm");
  writeStructureSetWithDamagedLength(folder / "structure-set.dcm", folder / "structure-set-damaged-length.dcm");
  writePolyData(folder);
  writeJson(folder / "contours.json");
  writeSegmentations(folder / "segmentation.seg.nrrd", folder / "fractional.seg.nrrd", folder / "segmentation-seg.dcm");
  return 0;
}

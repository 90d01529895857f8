// Segmentation files made by the tests: a 3D Slicer .seg.nrrd (written as Slicer writes it, header
// and raw voxels) and a DICOM SEG (written with DCMTK's dcmseg; a binary one's bits are packed
// here), of shapes given as functions of the physical (LPS) point, so meshes can be compared with
// the analytic shapes.
#ifndef SegmentationFileWriters_h
#define SegmentationFileWriters_h

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace slicemesh::testing
{

using PhysicalPoint = std::array<double, 3>;

/** An image grid: voxel (i, j, k) sits at origin + i s0 a0 + j s1 a1 + k s2 a2 (LPS mm). */
struct ImageGrid
{
  std::array<int, 3> size{ 1, 1, 1 };
  std::array<double, 3> spacing{ 1, 1, 1 };
  PhysicalPoint origin{ 0, 0, 0 };
  std::array<PhysicalPoint, 3> axes{ { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } }; ///< unit vectors
  PhysicalPoint point(int i, int j, int k) const;
};

/** One segment of a .seg.nrrd. Fields left empty are not written (as in files of older Slicers). */
struct SlicerSegmentSpec
{
  std::string id;
  std::string name;
  std::string color;      ///< "r g b", 0..1
  std::string layer;      ///< SegmentN_Layer
  std::string labelValue; ///< SegmentN_LabelValue
  std::string extent;     ///< SegmentN_Extent: "i0 i1 j0 j1 k0 k1", the voxels the segment may have
};

/** Writes a .seg.nrrd of unsigned char voxels: 3-D for one layer, else 4-D with a leading list axis
 *  ("kinds: list domain domain domain"), as 3D Slicer writes overlapping segments. Layer l's voxel
 *  (i, j, k) is layers[l](grid.point(i, j, k)); `extraFields` are written as they are. The voxels
 *  are raw, or gzip-compressed as Slicer writes them by default. */
void writeSlicerSegmentation(const std::filesystem::path& path, const ImageGrid& grid,
                             const std::vector<std::function<unsigned char(const PhysicalPoint&)>>& layers,
                             const std::vector<SlicerSegmentSpec>& segments,
                             const std::vector<std::string>& extraFields = {}, bool gzip = false);

/** Writes a .seg.nrrd as 3D Slicer writes a segmentation whose source representation is "Fractional
 *  labelmap": signed char voxels (`voxelType` names another NRRD type, for files Slicer does not
 *  write), a layer per segment (a 3-D file for one), the Segmentation_ fields Slicer writes (master
 *  representation, conversion parameters with the threshold fraction 0.5), and no scalar range (it
 *  stays in Slicer's memory). Layer l's voxel (i, j, k) is layers[l](grid.point(i, j, k)), cast to
 *  the voxel type; `extraFields` are written as they are. */
void writeSlicerFractionalSegmentation(const std::filesystem::path& path, const ImageGrid& grid,
                                       const std::vector<std::function<int(const PhysicalPoint&)>>& layers,
                                       const std::vector<SlicerSegmentSpec>& segments,
                                       const std::vector<std::string>& extraFields = {}, bool gzip = false,
                                       const std::string& voxelType = "signed char");

/** The value Slicer's fractional labelmap holds for the voxel centred at `centre`: -108 plus how
 *  many of the voxel's 6 x 6 x 6 evenly spread sample points are inside the shape (as Slicer sums
 *  216 shifted binary labelmaps), from -108 (empty) to 108 (full). */
int slicerFraction(const ImageGrid& grid, const PhysicalPoint& centre, const std::function<bool(const PhysicalPoint&)>& inside);

/** One segment of a DICOM SEG: inside(point) is the fraction of the segment at a pixel centre (0..1;
 *  a binary file sets the pixels where it is at least one half). */
struct DicomSegmentSpec
{
  std::string label;
  std::array<double, 3> rgb{ 0.5, 0.5, 0.5 }; ///< 0..1, stored as the recommended CIELab colour
  std::function<double(const PhysicalPoint&)> inside;
};

/** Writes a DICOM SEG on the grid (rows = size[1], columns = size[0], frames along axes[2]): one
 *  frame per segment and slice where the segment has a pixel (as SEG writers leave empty frames
 *  out), in segment order. Binary when maxFraction is 0, else fractional (probability) with that
 *  Maximum Fractional Value. `framePosition`, when given, replaces the Image Position (Patient)
 *  written for slice k (to make files whose frames are off the grid). A binary file's frames are
 *  packed here, as one bit stream as the standard says (a frame starts at bit n * rows * columns,
 *  mid-byte when rows * columns is not a multiple of 8), not by dcmseg, which packs those otherwise. */
void writeDicomSegmentation(const std::filesystem::path& path, const ImageGrid& grid,
                            const std::vector<DicomSegmentSpec>& segments, unsigned int maxFraction = 0,
                            const std::function<PhysicalPoint(int k)>& framePosition = {});

/** Rewrites the DICOM file with only the first `pixelDataBytes` bytes of its Pixel Data and, when
 *  numberOfFrames is not negative, that Number of Frames (the per-frame functional groups stay): a
 *  well-formed file whose frames lack pixels. */
void cutDicomFrames(const std::filesystem::path& path, std::size_t pixelDataBytes, long numberOfFrames = -1);

/** Rewrites the DICOM SEG's segment numbers, 1, 2, ... becoming numbers[0], numbers[1], ... in its
 *  Segment Sequence and in every frame's Referenced Segment Number: a file of a writer that does not
 *  number its segments from 1 up. */
void renumberDicomSegments(const std::filesystem::path& path, const std::vector<unsigned short>& numbers);

} // namespace slicemesh::testing

#endif

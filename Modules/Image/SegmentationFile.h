// Segmentation files: 3D Slicer's .seg.nrrd and DICOM SEG, read as named, coloured segments, each
// a label value in one of the file's label maps (layers). Overlapping segments live in different
// layers, so every segment can be meshed whole.
#ifndef SegmentationFile_h
#define SegmentationFile_h

#include "VolumeReader.h"

#include <array>
#include <string>
#include <vector>

namespace slicemesh
{

struct SegmentationFile
{
  struct Segment
  {
    int number = 0;        ///< 1, 2, ...: Slicer's SegmentN_ is number N + 1; DICOM's Segment Number
    std::string id;        ///< Slicer's SegmentN_ID; DICOM: the Segment Number as text
    std::string name;      ///< SegmentN_Name / Segment Label
    std::array<unsigned char, 4> rgba{ 128, 128, 128, 255 };
    std::size_t layer = 0; ///< index into `layers`
    int labelValue = 1;    ///< the segment's voxel value in its layer
  };

  std::string format;                        ///< "3D Slicer segmentation" or "DICOM SEG", for messages
  std::vector<ScalarVolume::Pointer> layers; ///< label maps in the file's physical space (LPS)
  std::vector<Segment> segments;             ///< in the file's order
};

enum class SegmentationFormat
{
  None,      ///< not a segmentation file: an ordinary volume (or unreadable: readVolume says why)
  SlicerNrrd, ///< a NRRD file whose header has SegmentN_ fields
  DicomSeg   ///< a DICOM file with Modality SEG
};

/** The segmentation format of a file, from its content (not its name); reads only the header. */
SegmentationFormat segmentationFormatOf(const std::string& path);

/** 3D Slicer's .seg.nrrd: one layer per volume of its list axis (one for a 3-D file), the segments
 *  from the SegmentN_Name, _ID, _Color (r g b, 0..1), _Layer and _LabelValue fields. Files of Slicer
 *  versions without _Layer / _LabelValue (one layer per segment, value 1) are read too. A fractional
 *  labelmap (one layer per segment) comes back as binary: each layer its segment's label map, value
 *  1 where the fraction is at least one half within the segment's _Extent (FractionalLabelmap.h).
 *  Throws slicemesh::Error with a one-line message naming the file when it cannot be read or its
 *  fields contradict its image (a layer that does not exist, two fractional segments in one layer, a
 *  fraction outside its range, a stored representation that is no labelmap). */
SegmentationFile readSlicerSegmentation(const std::string& path);

/** DICOM SEG (binary or fractional; fractional voxels count from half the maximum fraction up):
 *  one layer per segment, label value 1, covering the slices its frames are on. The frames are
 *  placed by their Plane Position (Patient), the Plane Orientation and the Pixel Measures, on one
 *  grid of slices along the orientation's normal. The colour is the Recommended Display CIELab
 *  Value converted to RGB (a generated colour when absent). Throws slicemesh::Error with a one-line
 *  message naming the file when it cannot be read or its frames are not on one grid. */
SegmentationFile readDicomSegmentation(const std::string& path);

/** The reader for the file's format; throws slicemesh::Error for SegmentationFormat::None. */
SegmentationFile readSegmentationFile(const std::string& path);

} // namespace slicemesh

#endif

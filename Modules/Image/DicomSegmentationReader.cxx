// DICOM SEG through DCMTK's dcmseg: every frame is one slice of one segment, placed in patient
// space by its functional groups. The frames of all segments are put on one grid of slices along
// the normal of their shared orientation; each segment gets a label map of the slices it is on.
#include "DicomImageReaders.h"

#include "ColorTable.h"
#include "MemoryBudget.h"

#include "Core/SliceMeshTypes.h"

#include "dcmtk/config/osconfig.h"
#include "dcmtk/dcmdata/dcdeftag.h"
#include "dcmtk/dcmdata/dcfilefo.h"
#include "dcmtk/dcmfg/fginterface.h"
#include "dcmtk/dcmfg/fgpixmsr.h"
#include "dcmtk/dcmfg/fgplanor.h"
#include "dcmtk/dcmfg/fgplanpo.h"
#include "dcmtk/dcmfg/fgseg.h"
#include "dcmtk/dcmiod/cielabutil.h"
#include "dcmtk/dcmseg/segdoc.h"
#include "dcmtk/dcmseg/segment.h"
#include "dcmtk/oflog/oflog.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

using Vector3 = Eigen::Vector3d;

/** One frame as the functional groups describe it. */
struct FrameGeometry
{
  Vector3 position = Vector3::Zero(); ///< Image Position (Patient) of the first pixel, LPS mm
  Vector3 row = Vector3::Zero();      ///< Image Orientation (Patient): along a row (columns increase)
  Vector3 column = Vector3::Zero();   ///< down a column
  double rowSpacing = 0.0, columnSpacing = 0.0; ///< Pixel Spacing: between rows, between columns
  double sliceSpacing = 0.0;                    ///< Spacing Between Slices, 0 when absent
  double sliceThickness = 0.0;                  ///< Slice Thickness, 0 when absent
  Uint16 segment = 0;                           ///< Referenced Segment Number
};

/** DCMTK reports through its own logger on stderr; SliceMesh reports each failure once, in one line. */
void silenceDcmtkLog()
{
  static const bool silenced = (OFLog::configure(OFLogger::OFF_LOG_LEVEL), true);
  (void)silenced;
}

FrameGeometry frameGeometry(const std::string& path, FGInterface& groups, Uint32 frame)
{
  auto missing = [&](const std::string& what)
  { return Error(path + ": frame " + std::to_string(frame + 1) + " has no " + what); };
  FrameGeometry g;
  auto* position = dynamic_cast<FGPlanePosPatient*>(groups.get(frame, DcmFGTypes::EFG_PLANEPOSPATIENT));
  if (!position || position->getImagePositionPatient(g.position[0], g.position[1], g.position[2]).bad())
    throw missing("Plane Position (Patient)");
  auto* orientation = dynamic_cast<FGPlaneOrientationPatient*>(groups.get(frame, DcmFGTypes::EFG_PLANEORIENTPATIENT));
  if (!orientation || orientation
                        ->getImageOrientationPatient(g.row[0], g.row[1], g.row[2], g.column[0], g.column[1],
                                                     g.column[2])
                        .bad())
    throw missing("Plane Orientation (Patient)");
  auto* measures = dynamic_cast<FGPixelMeasures*>(groups.get(frame, DcmFGTypes::EFG_PIXELMEASURES));
  if (!measures || measures->getPixelSpacing(g.rowSpacing, 0).bad() || measures->getPixelSpacing(g.columnSpacing, 1).bad())
    throw missing("Pixel Spacing");
  Float64 value = 0.0;
  if (measures->getSpacingBetweenSlices(value).good())
    g.sliceSpacing = value;
  if (measures->getSliceThickness(value).good())
    g.sliceThickness = value;
  auto* segmentation = dynamic_cast<FGSegmentation*>(groups.get(frame, DcmFGTypes::EFG_SEGMENTATION));
  if (!segmentation || segmentation->getReferencedSegmentNumber(g.segment).bad())
    throw missing("Referenced Segment Number");
  return g;
}

/** The grid every frame lies on: in-plane axes and spacing of the frames, slices along their
 *  normal from the lowest frame up. */
struct SliceGrid
{
  Vector3 origin = Vector3::Zero();
  Vector3 axes[3];
  double spacing[3]{};
  std::vector<long> sliceOfFrame;
  long slices = 0;
};

SliceGrid sliceGrid(const std::string& path, const std::vector<FrameGeometry>& frames)
{
  const FrameGeometry& first = frames.front();
  SliceGrid grid;
  const Vector3 row = first.row, column = first.column;
  const double rowLength = row.norm(), columnLength = column.norm();
  if (!(rowLength > 0.5 && columnLength > 0.5) || std::abs(row.dot(column)) > 1e-3 * rowLength * columnLength)
    throw Error(path + ": the Image Orientation (Patient) is not two perpendicular directions");
  grid.axes[0] = row / rowLength;
  grid.axes[1] = column / columnLength;
  grid.axes[2] = grid.axes[0].cross(grid.axes[1]);
  grid.spacing[0] = first.columnSpacing; // neighbours along a row are a column apart
  grid.spacing[1] = first.rowSpacing;
  if (!(grid.spacing[0] > 0.0 && grid.spacing[1] > 0.0 && std::isfinite(grid.spacing[0]) && std::isfinite(grid.spacing[1])))
    throw Error(path + ": the Pixel Spacing is not two positive numbers");

  std::vector<double> heights;
  for (const FrameGeometry& f : frames)
  {
    for (int a = 0; a < 3; ++a)
      if (std::abs(f.row[a] - row[a]) > 1e-4 || std::abs(f.column[a] - column[a]) > 1e-4)
        throw Error(path + ": the frames have different orientations; SliceMesh needs parallel slices");
    if (std::abs(f.rowSpacing - first.rowSpacing) > 1e-4 * first.rowSpacing ||
        std::abs(f.columnSpacing - first.columnSpacing) > 1e-4 * first.columnSpacing)
      throw Error(path + ": the frames have different pixel spacings");
    heights.push_back(f.position.dot(grid.axes[2]));
  }
  const auto lowest = std::min_element(heights.begin(), heights.end()) - heights.begin();
  grid.origin = frames[lowest].position;

  // The slice spacing: the file's Spacing Between Slices, else the smallest gap between distinct
  // frame heights, else (one slice) its thickness or the in-plane spacing.
  std::vector<double> distinct = heights;
  std::sort(distinct.begin(), distinct.end());
  constexpr double samePlane = 1e-3; // mm
  distinct.erase(std::unique(distinct.begin(), distinct.end(),
                             [&](double a, double b) { return std::abs(a - b) < samePlane; }),
                 distinct.end());
  double spacing = first.sliceSpacing;
  if (!(spacing > 0.0))
  {
    spacing = 0.0;
    for (std::size_t n = 1; n < distinct.size(); ++n)
      spacing = spacing == 0.0 ? distinct[n] - distinct[n - 1] : std::min(spacing, distinct[n] - distinct[n - 1]);
  }
  if (!(spacing > 0.0))
    spacing = first.sliceThickness > 0.0 ? first.sliceThickness : std::min(grid.spacing[0], grid.spacing[1]);
  grid.spacing[2] = spacing;

  for (std::size_t n = 0; n < frames.size(); ++n)
  {
    const Vector3 offset = frames[n].position - grid.origin;
    for (int a = 0; a < 2; ++a)
      if (std::abs(offset.dot(grid.axes[a])) > 1e-3 + 1e-2 * grid.spacing[a])
        throw Error(path + ": frame " + std::to_string(n + 1) +
                    " is shifted in its plane against the others; SliceMesh needs the frames on one grid");
    const double step = offset.dot(grid.axes[2]) / spacing;
    const long slice = std::lround(step);
    if (std::abs(step - static_cast<double>(slice)) > 0.02)
    {
      std::ostringstream message;
      message << path << ": frame " << n + 1 << " lies " << offset.dot(grid.axes[2])
              << " mm above the lowest frame, not a whole number of slices of " << spacing << " mm";
      throw Error(message.str());
    }
    grid.sliceOfFrame.push_back(slice);
    grid.slices = std::max(grid.slices, slice + 1);
  }
  return grid;
}

/** An empty label map of the slices [first, last] of the grid (the region's index starts at `first`,
 *  so physical points are those of the whole grid). */
ScalarVolume::Pointer layerOf(const SliceGrid& grid, long columns, long rows, long first, long last)
{
  auto volume = ScalarVolume::New();
  ScalarVolume::PointType origin;
  ScalarVolume::SpacingType spacing;
  ScalarVolume::DirectionType direction;
  for (unsigned int r = 0; r < 3; ++r)
  {
    origin[r] = grid.origin[r];
    spacing[r] = grid.spacing[r];
    for (unsigned int c = 0; c < 3; ++c)
      direction[r][c] = grid.axes[c][r];
  }
  volume->SetOrigin(origin);
  volume->SetSpacing(spacing);
  volume->SetDirection(direction);
  ScalarVolume::IndexType index{ { 0, 0, first } };
  ScalarVolume::SizeType size{ { static_cast<std::size_t>(columns), static_cast<std::size_t>(rows),
                                 static_cast<std::size_t>(last - first + 1) } };
  volume->SetRegions(ScalarVolume::RegionType(index, size));
  volume->Allocate(true);
  return volume;
}

/** The Pixel Data of a BINARY segmentation, one bit a pixel: its frames are one bit stream (frame n
 *  starts at bit n * rows * columns), read here rather than through DCMTK, whose frame extraction
 *  (3.6.7) misaligns the frames that start mid-byte. Enough bytes for every frame, else an error. */
const Uint8* binaryPixelData(const std::string& path, DcmDataset& dataset, std::size_t frames, Uint16 rows, Uint16 columns)
{
  const Uint8* bytes = nullptr;
  unsigned long length = 0;
  const bool read = dataset.findAndGetUint8Array(DCM_PixelData, bytes, &length).good() && bytes;
  const std::size_t needed = (frames * rows * columns + 7) / 8;
  if (!read || length < needed)
    throw Error(path + ": the pixel data has " + std::to_string(read ? length : 0) + " bytes; " +
                std::to_string(frames) + " frames of " + std::to_string(rows) + " x " + std::to_string(columns) +
                " pixels need " + std::to_string(needed));
  return bytes;
}

/** Pixel p of frame n (0 or 1 in `out`) is bit n * pixels + p of the stream; bit i of the stream is
 *  bit i % 8 of byte i / 8 (the least significant bit first). */
void unpackBinaryFrame(const Uint8* stream, std::size_t frame, std::size_t pixels, std::vector<Uint8>& out)
{
  out.resize(pixels);
  const std::size_t first = frame * pixels;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    const std::size_t bit = first + p;
    out[p] = (stream[bit / 8] >> (bit % 8)) & 1u;
  }
}

/** A FRACTIONAL frame: one byte a pixel, as DCMTK extracts it. */
const Uint8* fractionalFrame(const std::string& path, DcmSegmentation& segmentation, std::size_t frame, std::size_t pixels)
{
  const DcmIODTypes::Frame* pixelData = segmentation.getFrame(frame);
  if (!pixelData || !pixelData->pixData || pixelData->length < pixels)
    throw Error(path + ": frame " + std::to_string(frame + 1) + " has no pixel data or too little of it");
  return pixelData->pixData;
}

/** The Segment Number the file gives the segment at `position` (1, 2, ...) of its Segment Sequence;
 *  the position itself where it gives none. (DCMTK numbers segments by position.) */
std::size_t storedSegmentNumber(DcmDataset& dataset, std::size_t position)
{
  DcmItem* item = nullptr;
  Uint16 number = 0;
  if (dataset.findAndGetSequenceItem(DCM_SegmentSequence, item, static_cast<signed long>(position - 1)).good() && item &&
      item->findAndGetUint16(DCM_SegmentNumber, number).good() && number > 0)
    return number;
  return position;
}

} // namespace

bool isDicomSegmentation(const std::string& path)
{
  silenceDcmtkLog();
  DcmFileFormat file;
  // Parsing stops after the Modality (0008,0060): a SEG whose frames are damaged or cut short is
  // still recognised, and its reader says what is wrong with it.
  const DcmTagKey afterModality(0x0008, 0x0061);
  file.loadFileUntilTag(path.c_str(), EXS_Unknown, EGL_noChange, DCM_MaxReadLength, ERM_autoDetect, afterModality);
  OFString modality;
  return file.getDataset()->findAndGetOFString(DCM_Modality, modality).good() && modality == "SEG";
}

SegmentationFile readDicomSegmentationFile(const std::string& path)
{
  silenceDcmtkLog();
  DcmFileFormat dicom;
  OFCondition status = dicom.loadFile(path.c_str());
  if (status.bad())
    throw Error(path + ": cannot read the DICOM file (a truncated or damaged file?): " + status.text());
  DcmDataset& dataset = *dicom.getDataset();
  OFString modality;
  dataset.findAndGetOFString(DCM_Modality, modality);
  if (modality != "SEG")
    throw Error(path + ": a DICOM file of modality '" + std::string(modality.c_str()) +
                "', not a segmentation (SEG)");
  Uint16 rows = 0, columns = 0, maximumFraction = 0;
  dataset.findAndGetUint16(DCM_Rows, rows);
  dataset.findAndGetUint16(DCM_Columns, columns);
  dataset.findAndGetUint16(DCM_MaximumFractionalValue, maximumFraction);

  DcmSegmentation* loaded = nullptr;
  status = DcmSegmentation::loadDataset(dataset, loaded);
  const std::unique_ptr<DcmSegmentation> segmentation(loaded);
  if (status.bad() || !segmentation)
    throw Error(path + ": cannot read the DICOM segmentation: " + status.text());
  const bool binary = segmentation->getSegmentationType() == DcmSegTypes::ST_BINARY;
  if (!binary && segmentation->getSegmentationType() != DcmSegTypes::ST_FRACTIONAL)
    throw Error(path + ": a segmentation neither BINARY nor FRACTIONAL");
  if (!binary && maximumFraction == 0)
    throw Error(path + ": a fractional segmentation without a Maximum Fractional Value");
  const std::size_t frameCount = segmentation->getNumberOfFrames();
  if (rows == 0 || columns == 0)
    throw Error(path + ": the frames have no rows or columns");

  SegmentationFile file;
  file.format = "DICOM SEG";
  // The standard numbers segments 1, 2, ... in their order; some writers number them otherwise (3
  // and 7), and the frames refer to those numbers: each segment keeps the number it was given.
  std::map<std::size_t, std::size_t> positionOfNumber;
  for (std::size_t position = 1; position <= segmentation->getNumberOfSegments(); ++position)
  {
    DcmSegment* dicomSegment = segmentation->getSegment(position);
    if (!dicomSegment)
      throw Error(path + ": segment " + std::to_string(position) + " is missing (segments are numbered from 1 up)");
    const std::size_t number = storedSegmentNumber(dataset, position);
    if (!positionOfNumber.emplace(number, position).second)
      throw Error(path + ": two segments are numbered " + std::to_string(number));
    SegmentationFile::Segment segment;
    segment.number = static_cast<int>(number);
    segment.id = std::to_string(number);
    OFString label;
    dicomSegment->getSegmentLabel(label);
    segment.name = label.empty() ? "Segment_" + segment.id : std::string(label.c_str());
    Uint16 l = 0, a = 0, b = 0;
    if (dicomSegment->getRecommendedDisplayCIELabValue(l, a, b).good())
    {
      double rgb[3];
      IODCIELabUtil::dicomLab2RGB(rgb[0], rgb[1], rgb[2], l, a, b);
      for (int c = 0; c < 3; ++c)
        segment.rgba[c] = static_cast<unsigned char>(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 255.0));
    }
    else
      segment.rgba = ColorTable::generatedColor(segment.number);
    segment.layer = position - 1;
    segment.labelValue = 1;
    file.segments.push_back(segment);
  }
  if (file.segments.empty())
    throw Error(path + ": a DICOM segmentation without segments");

  std::vector<FrameGeometry> frames;
  for (std::size_t n = 0; n < frameCount; ++n)
  {
    frames.push_back(frameGeometry(path, segmentation->getFunctionalGroups(), static_cast<Uint32>(n)));
    const auto listed = positionOfNumber.find(frames.back().segment);
    if (listed == positionOfNumber.end())
      throw Error(path + ": frame " + std::to_string(n + 1) + " refers to segment " +
                  std::to_string(frames.back().segment) + ", which the file does not list");
    frames.back().segment = static_cast<Uint16>(listed->second); // from here on, the segment's position
  }

  // Each segment's slices: its label map covers them only.
  std::vector<std::pair<long, long>> range(file.segments.size(), { 0, -1 });
  SliceGrid grid{ {}, { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { 1, 1, 1 }, {}, 0 }; // no frames: every segment empty
  if (!frames.empty())
  {
    grid = sliceGrid(path, frames);
    for (std::size_t n = 0; n < frames.size(); ++n)
    {
      auto& [first, last] = range[frames[n].segment - 1];
      const long slice = grid.sliceOfFrame[n];
      if (first > last)
        first = last = slice;
      first = std::min(first, slice);
      last = std::max(last, slice);
    }
  }
  double voxels = 0.0;
  for (const auto& [first, last] : range)
    voxels += static_cast<double>(columns) * rows * static_cast<double>(std::max(last - first + 1, 1L));
  checkMemoryBudget(path + ": the label maps of " + std::to_string(file.segments.size()) + " segments",
                    runMemoryBytes(voxels, 4.0)); // float label maps
  for (std::size_t s = 0; s < file.segments.size(); ++s)
  {
    const auto [first, last] = range[s];
    // A segment without frames is empty: a single empty voxel stands for it.
    file.layers.push_back(first > last ? layerOf(grid, 1, 1, 0, 0) : layerOf(grid, columns, rows, first, last));
  }

  const std::size_t pixels = static_cast<std::size_t>(rows) * columns;
  const Uint8* bitStream = binary && !frames.empty() ? binaryPixelData(path, dataset, frames.size(), rows, columns) : nullptr;
  std::vector<Uint8> unpacked;
  for (std::size_t n = 0; n < frames.size(); ++n)
  {
    const Uint8* values = nullptr;
    if (binary)
    {
      unpackBinaryFrame(bitStream, n, pixels, unpacked);
      values = unpacked.data();
    }
    else
      values = fractionalFrame(path, *segmentation, n, pixels);
    ScalarVolume* layer = file.layers[frames[n].segment - 1];
    const long slice = grid.sliceOfFrame[n] - layer->GetBufferedRegion().GetIndex()[2];
    float* out = layer->GetBufferPointer() + static_cast<std::size_t>(slice) * pixels;
    for (std::size_t p = 0; p < pixels; ++p)
    {
      const unsigned int value = values[p];
      // Several frames of one segment on one slice add up.
      if (binary ? value != 0 : 2u * value >= maximumFraction)
        out[p] = 1.0f;
    }
  }
  for (const ScalarVolume::Pointer& layer : file.layers)
    checkVolumeGeometry(path, layer);
  return file;
}

} // namespace slicemesh

// The structures a run meshes, and where they come from: the one mask of a one-mesh run, the labels
// of a label map or the segments of a segmentation file (each a mask cropped to its box), or the
// ROIs of a structure set (each a stack of contours). From here on all go through the same stages.
#ifndef PipelineStructures_h
#define PipelineStructures_h

#include "ColorTable.h"
#include "Contours/ContourStacking.h"
#include "LabelIndex.h"
#include "Meshing/MeshContours.h"
#include "SegmentationFile.h"
#include "SliceMeshPipeline.h"
#include "StoredVolume.h"
#include "StructureSet.h"
#include "VolumeReader.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace slicemesh::cli
{

/** One structure on its way through the run: the mask, one label of a label map, or one ROI of a
 *  structure set. A mask is traced into contours; an ROI comes with its contours. */
struct Structure
{
  LabelReport report;                              ///< label (the ROI number), name, file, figures, error
  std::array<unsigned char, 4> rgba{ 128, 128, 128, 255 };
  /** Null for an ROI; released once its contours are traced (the stack frame stays in `contours`). */
  MaskVolume::Pointer mask;
  StackedContours contours;                        ///< an ROI's stack, frame and grid spacing; a mask's frame
  MeshedContours meshing;
  bool live() const { return report.meshed(); } ///< neither failed nor dropped
  SliceFrame frame() const { return this->contours.frame; }
};

/** "label 3 (Hippocampus): ", "ROI 2 (PTV): " or nothing (a one-mesh run). */
std::string who(const Structure& s, const std::string& noun);

/** The single mask of a one-mesh run, after --minimumComponentVolume. `automaticChoice` receives
 *  the line saying which input kind was chosen from the voxels, when it was chosen so. */
Structure maskStructure(StoredVolume volume, const PipelineSettings& settings, std::string* automaticChoice);

/** What one structure of a multi-label run is cut from: a label value of one label map (the volume,
 *  or a layer of a segmentation file) with its box, and the number, name and colour it goes by. */
struct LabelSource
{
  StoredVolume labelMap;
  LabelExtent extent; ///< no voxels: an empty segment
  int number = 0;     ///< the label value, or the segment's number
  std::string name;
  std::array<unsigned char, 4> rgba{ 128, 128, 128, 255 };
};

/** Every non-zero label of a label map, in increasing order, named and coloured by the table; one
 *  pass over the volume finds them all. `negative`: whether negative values are labels (indexLabels). */
std::vector<LabelSource> labelMapSources(const StoredVolume& volume, const ColorTable& colors, NegativeLabels negative);

/** Every segment of a segmentation file, in the file's order, named and coloured by the file; one
 *  pass over each layer finds them all. A segment without voxels keeps an empty extent. */
std::vector<LabelSource> segmentSources(const SegmentationFile& file, const std::string& path);

/** One structure per source asked for (by number: label values or segment numbers; by name, any
 *  case; neither: all), each a mask cropped to its box. An empty source (a segment without voxels)
 *  is reported and dropped. */
std::vector<Structure> labelStructures(std::vector<LabelSource> sources, const std::vector<int>& numbers,
                                       const std::vector<std::string>& names, bool segments,
                                       const PipelineSettings& settings);

/** The warning to give when the structure set names Frames of Reference and the reference image's
 *  (a DICOM image's) is not among them: the contours may have been drawn on another image, whose
 *  slices and spacing would then stack them wrongly. Nothing when either does not say. */
std::optional<std::string> frameOfReferenceWarning(const StructureSet& set, const VolumeGeometry& reference,
                                                   const ContourInputSettings& contours);

/** The warning to give when most pieces of a one-mesh run are specks (a few voxels each) and there
 *  are many (speckNoiseCount): noise, above all from thresholding a noisy image, which costs most of
 *  the run and gives a mesh of thousands of grains. It names the options that remove them first.
 *  Nothing otherwise: an atlas label's specks are few, and a multi-label run's pieces are its labels'. */
std::optional<std::string> speckNoiseWarning(const FinishedSurface& surface);

/** How many specks make speckNoiseWarning speak. */
constexpr std::size_t speckNoiseCount = 1000;

/** Whether a finished structure encloses more than 5% less (or more) than the volume it was given
 *  (its voxels'; RunQuality::targetVolume): where its pieces crossed once finished they keep their
 *  tiled shape, which lies inside, and a speck follows its voxels only half way. Volumetry is a main
 *  use: such a shortfall is said (on stdout, a note), not left to the report. */
bool volumeShortfall(const LabelReport& report);

/** The one line for the structures `shortOfVolume` (indices into `structures`, volumeShortfall):
 *  how many, and the first's volumes: of its voxels, or `fromContours`, of its contours' slabs (an
 *  ROI's volume as a planning system counts it). */
std::string volumeShortfallWarning(const std::vector<Structure>& structures, const std::vector<std::size_t>& shortOfVolume,
                                   const std::string& noun, bool fromContours);

/** One structure per ROI asked for (every ROI by default), in the file's order: its contours as a
 *  stack along the reference image's slice direction and spacing when they lie on its slices (else
 *  along their own normal, with one warning for the set), crossings and keyholes repaired.
 *  An ROI whose contours lie in one slice is one slice spacing thick, the usual spacing of the other ROIs. An ROI that cannot
 *  be stacked (no contours, no spacing known) carries its error; every fault is one warning line. */
std::vector<Structure> roiStructures(const StructureSet& set, const std::optional<VolumeGeometry>& reference,
                                     const PipelineSettings& settings);

/** The contour points of a stack, over all its slices: what a structure's work grows with. */
std::size_t contourPoints(const ContourStack& stack);

} // namespace slicemesh::cli

#endif

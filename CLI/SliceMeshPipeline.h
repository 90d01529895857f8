// The run behind the command line: volume file in, mesh file(s) out, stage by stage. One path for
// one mesh of a mask and for one mesh per label: each structure (the mask, or a label) goes through
// the same meshing path (meshContours, Logic), stage by stage. Only wiring: every step is a library
// function of Modules/ or Logic/.
#ifndef SliceMeshPipeline_h
#define SliceMeshPipeline_h

#include "ContourInputSettings.h"
#include "ExitCodes.h"
#include "MeshWriter.h"
#include "Meshing/MeshingOptions.h"
#include "MultiLabelSettings.h"
#include "ProgressReporter.h"
#include "QualityReport.h"
#include "VolumeSegmentation.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace slicemesh::cli
{

struct PipelineSettings
{
  std::string inputVolume;
  std::string outputModel;
  SegmentationOptions segmentation;
  /** Connected components of the mask smaller than this (mm^3) are dropped; 0 keeps all. */
  double minimumComponentVolume = 0.0;
  /** In-plane Gaussian of the mask before its contours are traced (mm); 0: none. */
  double contourSmoothingSigma = 0.0;
  /** Every stage of the meshing path; automatic values are resolved for each mask's grid. */
  MeshingOptions meshing;
  CoordinateSystem coordinateSystem = CoordinateSystem::LPS;
  std::string reportFile;   ///< JSON quality report to write; empty: none
  std::string snapshotFile; ///< PNG picture coloured by triangle quality; empty: none
  /** Slicer's --returnparameterfile: written by the caller after the run, its folder checked before. */
  std::string returnParameterFile;
  /** One mesh per label of a label map. */
  MultiLabelSettings multiLabel;
  /** A structure set or contour file instead of the volume: one mesh per ROI, named, coloured and
   *  written as the labels of a multi-label run (multiLabel's output folder). */
  ContourInputSettings contours;
  /** Threads for the whole run (labels side by side, and the work inside each); 0: every core. */
  unsigned int threads = 0;
};

struct PipelineResult
{
  /** Of the mesh as written (measured in the stack frame: same volume); summed over the labels of a
   *  multi-label run. */
  MeshValidation validation;
  double seconds = 0.0;       ///< wall-clock time from reading to writing
  RunQuality quality;         ///< shape, Dirichlet energy, spacing ratio, seconds per stage
  SectionStatistics sections; ///< of the correspondence stage (notes of every label)
  /** Which input kind a one-mesh run chose from the voxels, and why; empty when --inputKind set it. */
  std::string inputKindChoice;
};

/** A stage failed; carries the exit code that names the kind of failure and a one-line message. */
class PipelineFailure : public std::runtime_error
{
public:
  PipelineFailure(ExitCode code, const std::string& message)
    : std::runtime_error(message)
    , Code(code)
  {
  }
  /** A run that wrote some structures before others failed: what it wrote, for the return values. */
  PipelineFailure(ExitCode code, const std::string& message, const PipelineResult& written)
    : std::runtime_error(message)
    , Code(code)
    , Written(std::make_shared<const PipelineResult>(written))
  {
  }
  ExitCode code() const { return this->Code; }
  /** What was written, when some structures were (else null). */
  const PipelineResult* written() const { return this->Written.get(); }

private:
  ExitCode Code;
  std::shared_ptr<const PipelineResult> Written;
};

/** The text on one line: errors and warnings are one line on stderr (Slicer logs each line on its own). */
std::string oneLine(std::string text);

/** The stages, in order, as ProgressReporter shows them. */
std::vector<ProgressStage> pipelineStages();

/** readVolume -> segmentVolume (one mask, or one cropped mask per label) -> per structure, stage by
 *  stage: contours traced and prepared, sections, tiling, validation, finishing (meshContours'
 *  stages) -> mapToPhysicalSpace -> writeMesh. Every check that needs no input (no output is an
 *  input or another output, the output folders exist and are writable, a snapshot can be rendered,
 *  the colour table reads) is made before any work, and any failure before the write throws
 *  PipelineFailure and writes nothing.
 *
 *  One mesh: the mesh written, its validation, shape, snapshot and report are the finished
 *  surface's; the Dirichlet energy is the tiling's. An invalid mesh is still written (the caller
 *  decides what that means).
 *
 *  A segmentation file (3D Slicer .seg.nrrd, DICOM SEG; detected from its content unless the input
 *  kind is Grayscale) is read instead of a volume and meshed one mesh per segment, as labels are,
 *  each segment numbered, named and coloured by the file (--labels, or --label, picks segments by
 *  number); a segment without voxels is reported (warning) and has no mesh.
 *
 *  One mesh per label (settings.multiLabel): labels in increasing order, each stage reported once,
 *  its progress label by label. A label that fails is reported (error) and skipped; the others are
 *  still written, into their own files and the merged output model with a per-triangle "Label" and
 *  "Color". --minimumComponentVolume drops a label left empty (warning, no file); the run fails with
 *  EmptySegmentation only when every label is dropped. The validation sums the labels' figures;
 *  after writing, MeshingFailed names the failed labels. `labels`, when given, receives each
 *  label's figures.
 *
 *  A structure set or contour file (settings.contours): read -> per ROI, its contours as a stack
 *  (stackContours: along the reference image's slice direction and spacing when they lie on its
 *  slices, read from its header alone; else along their own normal), crossings and keyholes
 *  repaired (repairContours) -> the same stages from the contours on, ROI by ROI as labels (an ROI
 *  that is empty, cannot be stacked or fails is reported and skipped; the others are written) ->
 *  the ROI's frame to physical space -> one file per ROI "<number>_<name>.<ext>" in the output
 *  folder and the merged model. A file that cannot be read is UnreadableInput; --rois naming no ROI, EmptySegmentation. */
PipelineResult runPipeline(const PipelineSettings& settings, ProgressReporter& progress,
                           std::vector<LabelReport>* labels = nullptr);

} // namespace slicemesh::cli

#endif

// The run behind the command line: volume file in, mesh file out, stage by stage.
// Only wiring: every step is a library function of Modules/ or Logic/.
#ifndef SliceMeshPipeline_h
#define SliceMeshPipeline_h

#include "ExitCodes.h"
#include "IntermediateSections.h"
#include "MultiLabelSettings.h"
#include "MeshValidation.h"
#include "MeshWriter.h"
#include "ProgressReporter.h"
#include "QualityReport.h"
#include "SurfaceReconstruction.h"
#include "VolumeSegmentation.h"

#include <stdexcept>
#include <string>

namespace slicemesh::cli
{

struct PipelineSettings
{
  std::string inputVolume;
  std::string outputModel;
  SegmentationOptions segmentation;
  /** Connected components of the mask smaller than this (mm^3) are dropped; 0 keeps all. */
  double minimumComponentVolume = 0.0;
  /** Correspondence by the distance rule, bridging and intermediate sections (all off by default). */
  UndersamplingOptions undersampling;
  ReconstructionOptions reconstruction;
  CoordinateSystem coordinateSystem = CoordinateSystem::LPS;
  /** Contour preprocessing between extraction and tiling (all off by default). */
  ContourOptions contours;
  std::string reportFile;   ///< JSON quality report to write; empty: none
  std::string snapshotFile; ///< PNG picture coloured by triangle quality; empty: none
  /** One mesh per label of a label map (runMultiLabelPipeline, MultiLabelPipeline.h). */
  MultiLabelSettings multiLabel;
};

struct PipelineResult
{
  MeshValidation validation; ///< of the mesh as written (measured in the stack frame: same volume)
  double seconds = 0.0;      ///< wall-clock time from reading to writing
  RunQuality quality;        ///< shape, Dirichlet energy, spacing ratio, seconds per stage
  SectionStatistics sections; ///< of the correspondence stage (intermediate sections inserted, notes)
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
  ExitCode code() const { return this->Code; }

private:
  ExitCode Code;
};

/** The stages, in order, as ProgressReporter shows them. */
std::vector<ProgressStage> pipelineStages();

/** readVolume -> segmentVolume -> extractContours -> insertIntermediateSections -> reconstructSurface -> validateMesh ->
 *  mapToPhysicalSpace -> writeMesh. An invalid mesh is still written (the caller decides what
 *  that means); any failure before the write throws PipelineFailure and writes nothing. */
PipelineResult runPipeline(const PipelineSettings& settings, ProgressReporter& progress);

} // namespace slicemesh::cli

#endif

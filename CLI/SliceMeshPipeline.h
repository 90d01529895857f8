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
#include "SurfaceFinishing.h"
#include "SurfaceReconstruction.h"
#include "VolumeSegmentation.h"

#include <array>
#include <stdexcept>
#include <string>

namespace slicemesh::cli
{

/** How the traced contours are shaped before tiling (--contourPreparation and its options). */
enum class ContourPreparation
{
  Automatic, ///< Smoothed when the slices are at least twice as thick as the pixels, else Traced
  Smoothed,  ///< Taubin smoothing, then resampling (to --contourPointSpacing, or automatic)
  Traced     ///< the traced marching-squares contours (resampled only to an explicit spacing)
};

struct ContourPreparationOptions
{
  ContourPreparation mode = ContourPreparation::Traced; ///< the best-shaped triangles (see the README's benchmark)
  int smoothingIterations = 30;  ///< Taubin lambda/mu pairs (Smoothed); 0: no smoothing
  double smoothingMaxShift = 0.0; ///< bound on each point's move (mm); 0: 0.3 of the smaller pixel side
};

/** The mode Automatic stands for, for pixels of size pixelX x pixelY and slices sliceSpacing apart. */
ContourPreparation resolvedPreparation(ContourPreparation mode, double pixelX, double pixelY, double sliceSpacing);

/** The point spacing resampling uses (mm): the explicit one when given, otherwise, for smoothed
 *  contours, the geometric mean of the smaller pixel side and the slice spacing (so thick slices
 *  get fewer, longer contour edges and the slabs fewer rows); 0 (keep the points) for traced ones. */
double resolvedPointSpacing(const ContourOptions& contours, ContourPreparation resolved, double pixelX, double pixelY,
                            double sliceSpacing);

/** The traced contours as the pipeline tiles them: smoothed (ContourSmoothing.h) when the
 *  preparation resolves to Smoothed, then simplified (ContourSimplification.h) and resampled to
 *  resolvedPointSpacing keeping each contour's area (ContourResampling.h), all crossing-free.
 *  spacing is the image's (x, y, slice) spacing in mm. */
ContourStack prepareContours(const ContourStack& traced, const ContourOptions& contours,
                             const ContourPreparationOptions& preparation, const std::array<double, 3>& spacing);

/** A mask's contours as the pipeline tiles them: traced (after the in-plane Gaussian of
 *  contours.smoothingSigma, if any), then prepareContours with the mask's spacing. */
ContourStack maskContours(const MaskVolume* mask, const ContourOptions& contours,
                          const ContourPreparationOptions& preparation);

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
  /** Smoothing and automatic resampling of the traced contours (before `contours` applies). */
  ContourPreparationOptions preparation;
  /** What happens to the tiling (SurfaceFinishing.h): smoothed and remeshed by default. A target
   *  edge length of 0 stands for automaticEdgeLength of the mask's spacing (resolvedFinishing). */
  SurfaceFinishingOptions finishing{ SurfaceFinish::Remeshed, {}, { 0.0 } };
  std::string reportFile;   ///< JSON quality report to write; empty: none
  std::string snapshotFile; ///< PNG picture coloured by triangle quality; empty: none
  /** One mesh per label of a label map (runMultiLabelPipeline, MultiLabelPipeline.h). */
  MultiLabelSettings multiLabel;
};

struct PipelineResult
{
  MeshValidation validation; ///< of the finished mesh as written (measured in the stack frame: same volume)
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

/** The finishing options for a mask of this spacing (mm): finishingOptionsFor(spacing) (the
 *  automatic edge length, the smoothing's displacement bound) with the finish, smoothing iterations
 *  and pass band of `finishing`, and its target edge length and displacement bound where they are
 *  above 0, so the remeshed surface's resolution follows the voxels unless one is given. */
SurfaceFinishingOptions resolvedFinishing(const SurfaceFinishingOptions& finishing,
                                          const std::array<double, 3>& spacing);

/** finishSurface with the options resolved for the mask's spacing, measured: the finished mesh's
 *  shape and the tiling's Dirichlet energy (measureRun), the finish applied and its fallback. A
 *  non-empty fallback is also printed as one "SliceMesh: warning: " line on stderr, after `who`
 *  (empty, or "label 3 (Name): "). */
FinishedSurface finishAndMeasure(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                                 const ContourStack& stack, const SurfaceFinishingOptions& finishing,
                                 const std::array<double, 3>& spacing, const std::string& who, RunQuality& quality);

/** Throws PipelineFailure(WriteFailed) when a snapshot is asked for (snapshotFile not empty) but
 *  cannot be rendered here (no X display, MeshSnapshot.h's snapshotAvailable): both the single- and
 *  the multi-label path call it before any work, so such a run writes no file. */
void requireSnapshotRenderer(const std::string& snapshotFile);

/** The stages, in order, as ProgressReporter shows them. */
std::vector<ProgressStage> pipelineStages();

/** readVolume -> segmentVolume -> extractContours -> insertIntermediateSections -> reconstructSurface -> validateMesh ->
 *  finishSurface -> mapToPhysicalSpace -> writeMesh. The mesh written, its validation, shape,
 *  snapshot and report are the finished surface's; the Dirichlet energy is the tiling's. An invalid mesh is still written (the caller decides what
 *  that means); any failure before the write throws PipelineFailure and writes nothing. */
PipelineResult runPipeline(const PipelineSettings& settings, ProgressReporter& progress);

} // namespace slicemesh::cli

#endif

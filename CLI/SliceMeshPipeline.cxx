#include "SliceMeshPipeline.h"

#include "ContourExtraction.h"
#include "ContourResampling.h"
#include "ContourSimplification.h"
#include "ContourSmoothing.h"
#include "SmallComponentRemoval.h"
#include "MeshSnapshot.h"
#include "MultiLabelPipeline.h"
#include "NiftiOrientation.h"
#include "VolumeReader.h"

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <sstream>
#include <unistd.h>
#include <iostream>

namespace slicemesh::cli
{

namespace
{

enum Stage : std::size_t
{
  Reading,
  Segmentation,
  Contours,
  Correspondence,
  Tiling,
  Validation,
  Finishing,
  Writing
};

/** Runs one step; a failure becomes a PipelineFailure with the given code. */
template <typename Step>
auto guarded(ExitCode code, Step&& step) -> decltype(step())
{
  try
  {
    return step();
  }
  catch (const PipelineFailure&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    throw PipelineFailure(code, e.what());
  }
}

std::size_t contourCount(const ContourStack& stack)
{
  std::size_t count = 0;
  for (const Slice& slice : stack.slices)
  {
    count += slice.contours.size();
  }
  return count;
}

} // namespace

ContourPreparation resolvedPreparation(ContourPreparation mode, double pixelX, double pixelY, double sliceSpacing)
{
  if (mode != ContourPreparation::Automatic)
    return mode;
  // Near-isotropic voxels: the traced contours of adjacent slices coincide along the voxel walls,
  // which the tiling turns into well-shaped rows; smoothing breaks that coincidence and, measured
  // on the benchmark's phantoms at 1 mm, costs more in angle quality and triangles than it gains
  // in distance. Thick slices: smoothing and longer contour edges win on distance and triangle
  // count, but lose on angles (6-13% of triangles under 30 degrees instead of 0.4-1.7%), which is
  // why this is an option and Traced the default.
  return sliceSpacing >= 2.0 * std::min(pixelX, pixelY) ? ContourPreparation::Smoothed : ContourPreparation::Traced;
}

double resolvedPointSpacing(const ContourOptions& contours, ContourPreparation resolved, double pixelX, double pixelY,
                            double sliceSpacing)
{
  if (contours.pointSpacing > 0.0 || resolved != ContourPreparation::Smoothed)
    return contours.pointSpacing;
  return std::sqrt(std::min(pixelX, pixelY) * sliceSpacing);
}

ContourStack prepareContours(const ContourStack& traced, const ContourOptions& contours,
                             const ContourPreparationOptions& preparation, const std::array<double, 3>& spacing)
{
  const ContourPreparation resolved = resolvedPreparation(preparation.mode, spacing[0], spacing[1], spacing[2]);
  ContourStack result = traced;
  if (resolved == ContourPreparation::Smoothed && preparation.smoothingIterations > 0)
  {
    ContourSmoothingOptions smoothing;
    smoothing.iterations = preparation.smoothingIterations;
    // 0.3 pixel: traced contours are at least 0.71 pixel apart (two voxels touching at a corner), so
    // points moving at most 0.3 pixel each cannot make them meet.
    smoothing.maxDisplacement =
      preparation.smoothingMaxShift > 0.0 ? preparation.smoothingMaxShift : 0.3 * std::min(spacing[0], spacing[1]);
    result = smoothContours(result, smoothing);
  }
  if (contours.simplificationTolerance > 0.0)
    result = simplifyContours(result, contours.simplificationTolerance);
  // Resampled contours keep their enclosed area: chords cut the corners of small structures.
  const double pointSpacing = resolvedPointSpacing(contours, resolved, spacing[0], spacing[1], spacing[2]);
  if (pointSpacing > 0.0)
    result = resampleContours(result, pointSpacing, /*keepArea=*/true);
  return result;
}

ContourStack maskContours(const MaskVolume* mask, const ContourOptions& contours,
                          const ContourPreparationOptions& preparation)
{
  const auto spacing = mask->GetSpacing();
  return prepareContours(extractContours(mask, contours.smoothingSigma), contours, preparation,
                         { spacing[0], spacing[1], spacing[2] });
}

SurfaceFinishingOptions resolvedFinishing(const SurfaceFinishingOptions& finishing,
                                          const std::array<double, 3>& spacing)
{
  // The library's finishing for this grid (automatic edge length, smoothing that moves no vertex
  // farther than a fraction of a voxel), with the command line's choices on top.
  SurfaceFinishingOptions resolved = finishingOptionsFor(spacing);
  resolved.finish = finishing.finish;
  resolved.smoothing.iterations = finishing.smoothing.iterations;
  resolved.smoothing.passBand = finishing.smoothing.passBand;
  if (finishing.smoothing.maxDisplacement > 0.0)
    resolved.smoothing.maxDisplacement = finishing.smoothing.maxDisplacement;
  resolved.remeshing.iterations = finishing.remeshing.iterations;
  if (finishing.remeshing.targetEdgeLength > 0.0)
    resolved.remeshing.targetEdgeLength = finishing.remeshing.targetEdgeLength;
  return resolved;
}

FinishedSurface finishAndMeasure(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                                 const ContourStack& stack, const SurfaceFinishingOptions& finishing,
                                 const std::array<double, 3>& spacing, const std::string& who, RunQuality& quality)
{
  const SurfaceFinishingOptions options = resolvedFinishing(finishing, spacing);
  FinishedSurface finished = finishSurface(tiling, tilingValidation, options);
  quality = measureRun(finished.mesh, tiling, stack);
  quality.genus = genusOf(finished.validation);
  quality.requestedFinish = finishName(options.finish);
  quality.finish = finishName(finished.finish);
  quality.fallback = finished.fallback;
  quality.smallPiecesAsTiled = finished.smallPiecesAsTiled;
  quality.piecesByFinish = finished.piecesByFinish;
  quality.unsmoothedVertices = finished.unsmoothedVertices;
  if (options.finish == SurfaceFinish::Remeshed)
    quality.targetEdgeLength = options.remeshing.targetEdgeLength;
  if (options.finish != SurfaceFinish::Tiled)
  {
    quality.smoothingIterations = options.smoothing.iterations;
    quality.smoothingPassBand = options.smoothing.passBand;
    quality.smoothingMaxDisplacement = options.smoothing.maxDisplacement;
  }
  if (!finished.fallback.empty())
  {
    std::string line = who + "surface finishing: " + finished.fallback;
    std::replace(line.begin(), line.end(), '\n', ' '); // one line: Slicer logs each line on its own
    std::cerr << "SliceMesh: warning: " << line << std::endl;
  }
  return finished;
}

void requireSnapshotRenderer(const std::string& snapshotFile)
{
  std::string reason;
  if (!snapshotFile.empty() && !snapshotAvailable(&reason))
    throw PipelineFailure(WriteFailed, "cannot render snapshot '" + snapshotFile + "': " + reason);
}

std::vector<ProgressStage> pipelineStages()
{
  // Weights: rough shares of a typical run's time, so the bar moves evenly.
  return { { "Reading", "Reading the input volume", 1.0 },
           { "Segmentation", "Segmenting the volume into a mask", 1.0 },
           { "Contours", "Tracing sub-voxel contours in every slice", 1.5 },
           { "Correspondence", "Matching contours between slices; intermediate sections where asked", 0.5 },
           { "Tiling", "Tiling and refining the slabs between slices", 5.0 },
           { "Validation", "Checking that the mesh is a closed, oriented surface", 1.0 },
           { "Finishing", "Remeshing and smoothing the surface in 3D", 2.0 },
           { "Writing", "Writing the mesh", 0.5 } };
}

PipelineResult runPipeline(const PipelineSettings& settings, ProgressReporter& progress)
{
  if (settings.multiLabel.enabled)
    return runMultiLabelPipeline(settings, progress);
  const auto began = std::chrono::steady_clock::now();
  StageTimes times;
  auto startStage = [&](Stage stage)
  {
    times.start(pipelineStages()[stage].name);
    progress.start(stage);
  };

  // Fail before the expensive work when the output could never be written.
  const std::filesystem::path output(settings.outputModel);
  const std::filesystem::path folder = output.has_parent_path() ? output.parent_path() : ".";
  if (!std::filesystem::is_directory(folder))
  {
    throw PipelineFailure(WriteFailed, "cannot write mesh '" + settings.outputModel + "': folder '" +
                                         folder.string() + "' does not exist");
  }
  // ... or cannot be written: probe with a file of our own (access() says yes to root on any folder).
  {
    std::string probe = (folder / ".SliceMesh-probe-XXXXXX").string();
    const int descriptor = ::mkstemp(probe.data());
    if (descriptor < 0)
    {
      const int error = errno;
      throw PipelineFailure(WriteFailed, "cannot write mesh '" + settings.outputModel + "': folder '" +
                                           folder.string() + "' is not writable (" + std::strerror(error) + ")");
    }
    ::close(descriptor);
    ::unlink(probe.c_str());
  }
  // ... and a picture that cannot be rendered here fails the run now, not after the mesh is written.
  requireSnapshotRenderer(settings.snapshotFile);

  startStage(Reading);
  const ScalarVolume::Pointer volume = guarded(UnreadableInput, [&] { return readVolume(settings.inputVolume); });
  if (const auto warning = niftiOrientationWarning(settings.inputVolume, volume))
    std::cerr << "SliceMesh: warning: " << *warning << std::endl;

  startStage(Segmentation);
  const MaskVolume::Pointer mask =
    guarded(EmptySegmentation, [&] { return segmentVolume(volume, settings.segmentation); });
  if (settings.minimumComponentVolume > 0.0)
  {
    const SmallComponentRemoval removal =
      guarded(MeshingFailed, [&] { return removeSmallComponents(mask, settings.minimumComponentVolume); });
    if (removal.removedComponents == removal.components)
    {
      std::ostringstream message;
      message << "every one of the " << removal.components << " connected components of the segmentation of '"
              << settings.inputVolume << "' is smaller than the minimum component volume "
              << settings.minimumComponentVolume << " mm^3 (the largest is " << removal.largestComponentVolume
              << " mm^3)";
      throw PipelineFailure(EmptySegmentation, message.str());
    }
  }

  startStage(Contours);
  const ContourStack contours =
    guarded(MeshingFailed, [&] { return maskContours(mask, settings.contours, settings.preparation); });
  if (contourCount(contours) == 0)
  {
    throw PipelineFailure(EmptySegmentation, "the segmentation of '" + settings.inputVolume + "' has no contours");
  }
  const SliceFrame frame = guarded(MeshingFailed, [&] { return sliceFrameOf(volume); });

  // Correspondence by the distance rule: bridging of distance-only pairs and sections in thick slabs
  // (a copy of the contours when both are off). Overlapping contours are matched inside the tiling.
  startStage(Correspondence);
  PipelineResult result;
  const ContourStack stack = guarded(
    MeshingFailed, [&] { return insertIntermediateSections(contours, settings.undersampling, &result.sections); });

  startStage(Tiling);
  ReconstructionOptions options = settings.reconstruction;
  options.progress = [&progress](double fraction) { progress.update(fraction); };
  const TriangleMesh stackMesh = guarded(MeshingFailed, [&] { return reconstructSurface(stack, options); });
  if (stackMesh.triangles.empty())
  {
    throw PipelineFailure(MeshingFailed, "the reconstruction of '" + settings.inputVolume + "' produced no triangles");
  }

  startStage(Validation);
  const MeshValidation tilingValidation = guarded(MeshingFailed, [&] { return validateMesh(stackMesh); });

  // From here on the mesh is the finished one: what is written, pictured and reported (only the
  // Dirichlet energy stays the tiling's).
  startStage(Finishing);
  const auto spacing = mask->GetSpacing();
  const FinishedSurface finished = guarded(
    MeshingFailed,
    [&]
    {
      return finishAndMeasure(stackMesh, tilingValidation, stack, settings.finishing,
                              { spacing[0], spacing[1], spacing[2] }, "", result.quality);
    });
  result.validation = finished.validation;

  startStage(Writing);
  const TriangleMesh physical =
    guarded(WriteFailed, [&] { return mapToPhysicalSpace(finished.mesh, frame, settings.coordinateSystem); });
  guarded(WriteFailed, [&] { writeMesh(physical, settings.coordinateSystem, settings.outputModel); });
  if (!settings.snapshotFile.empty())
    guarded(WriteFailed, [&] { writeSnapshot(physical, settings.snapshotFile); });
  progress.end();

  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  result.quality.stageSeconds = times.seconds();
  if (!settings.reportFile.empty())
  {
    guarded(WriteFailed,
            [&]
            {
              writeQualityReport(settings.reportFile, settings.inputVolume, settings.outputModel, result.validation,
                                 result.quality, result.seconds);
            });
  }
  return result;
}

} // namespace slicemesh::cli

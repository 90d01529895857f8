#include "MultiLabelPipeline.h"

#include "ColorTable.h"
#include "ContourExtraction.h"
#include "LabelIndex.h"
#include "MeshSnapshot.h"
#include "NiftiOrientation.h"
#include "SmallComponentRemoval.h"
#include "VolumeReader.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

namespace slicemesh::cli
{
namespace
{

using Clock = std::chrono::steady_clock;

/** The position of a stage in pipelineStages(), by name (the list grows as the pipeline does). */
std::size_t stageIndex(const std::string& name)
{
  const std::vector<ProgressStage> stages = pipelineStages();
  for (std::size_t n = 0; n < stages.size(); ++n)
    if (stages[n].name == name)
      return n;
  return 0;
}

double secondsSince(Clock::time_point began)
{
  return std::chrono::duration<double>(Clock::now() - began).count();
}

/** "037_Hippocampus_L.vtp": the value zero-padded to sort in label order, then the safe name. */
std::string labelFileName(const LabelColor& entry, int width, const std::string& extension)
{
  char value[32];
  std::snprintf(value, sizeof(value), "%0*d", width, entry.label);
  return std::string(value) + "_" + safeFileName(entry.name) + extension;
}

std::size_t contourPoints(const ContourStack& stack)
{
  std::size_t points = 0;
  for (const Slice& slice : stack.slices)
    for (const Polygon2& contour : slice.contours)
      points += contour.size();
  return points;
}

void accumulate(MeshValidation& sum, const MeshValidation& v)
{
  sum.vertices += v.vertices;
  sum.triangles += v.triangles;
  sum.degenerateTriangles += v.degenerateTriangles;
  sum.boundaryEdges += v.boundaryEdges;
  sum.nonManifoldEdges += v.nonManifoldEdges;
  sum.nonManifoldVertices += v.nonManifoldVertices;
  sum.inconsistentEdges += v.inconsistentEdges;
  sum.selfIntersections += v.selfIntersections;
  sum.selfIntersectionChecked = sum.selfIntersectionChecked && v.selfIntersectionChecked;
  sum.components += v.components;
  sum.eulerCharacteristic += v.eulerCharacteristic;
  sum.area += v.area;
  sum.volume += v.volume;
}

} // namespace

PipelineResult runMultiLabelPipeline(const PipelineSettings& settings, ProgressReporter& progress,
                                     std::vector<LabelMeshOutcome>* outcomes)
{
  const auto began = Clock::now();
  StageTimes times;
  namespace fs = std::filesystem;
  const MultiLabelSettings& multi = settings.multiLabel;
  const fs::path output(settings.outputModel);
  const fs::path folder = output.has_parent_path() ? output.parent_path() : ".";
  if (!fs::is_directory(folder))
    throw PipelineFailure(WriteFailed, "cannot write mesh '" + settings.outputModel + "': folder '" +
                                         folder.string() + "' does not exist");
  if (!multi.outputDirectory.empty() && !fs::is_directory(multi.outputDirectory))
  {
    std::error_code error;
    fs::create_directories(multi.outputDirectory, error);
    if (error)
      throw PipelineFailure(WriteFailed, "cannot create the output folder '" + multi.outputDirectory +
                                           "': " + error.message());
  }
  // A picture that cannot be rendered here (no X display) fails the run before any work or file.
  requireSnapshotRenderer(settings.snapshotFile);
  ColorTable colors;
  bool haveColors = false;
  if (!multi.colorTable.empty())
  {
    try
    {
      colors = ColorTable::read(multi.colorTable);
      haveColors = true;
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(BadArguments, e.what());
    }
  }

  times.start("Reading");
  progress.start(stageIndex("Reading"));
  ScalarVolume::Pointer volume;
  try
  {
    volume = readVolume(settings.inputVolume);
  }
  catch (const std::exception& e)
  {
    throw PipelineFailure(UnreadableInput, e.what());
  }
  if (const auto warning = niftiOrientationWarning(settings.inputVolume, volume))
    std::cerr << "SliceMesh: warning: " << *warning << std::endl;

  times.start("Segmentation");
  progress.start(stageIndex("Segmentation")); // one pass for every label's box
  std::vector<LabelExtent> extents;
  try
  {
    extents = indexLabels(volume);
  }
  catch (const std::exception& e)
  {
    throw PipelineFailure(EmptySegmentation, settings.inputVolume + ": " + e.what());
  }
  if (!multi.labels.empty())
  {
    std::set<int> wanted(multi.labels.begin(), multi.labels.end());
    std::vector<LabelExtent> chosen;
    for (const LabelExtent& e : extents)
      if (wanted.erase(e.label))
        chosen.push_back(e);
    if (!wanted.empty())
    {
      std::ostringstream message;
      message << settings.inputVolume << ": no voxel has label";
      for (int label : wanted)
        message << " " << label;
      message << " (" << extents.size() << " labels present)";
      throw PipelineFailure(EmptySegmentation, message.str());
    }
    extents = chosen;
  }
  if (extents.empty())
    throw PipelineFailure(EmptySegmentation, settings.inputVolume + ": every voxel is 0; nothing to mesh");
  if (!settings.segmentation.refinement.seeds.empty())
    std::cerr << "SliceMesh: warning: seed points are ignored when meshing every label separately" << std::endl;
  MaskRefinementOptions refinement = settings.segmentation.refinement;
  refinement.seeds.clear();

  const int width = extents.back().label >= 1000 ? 0 : 3;
  const std::string extension = output.extension().string();
  TriangleMesh merged;
  MeshAttributes mergedAttributes;
  PipelineResult result;
  result.validation.selfIntersectionChecked = true;
  std::vector<std::string> failures;
  std::vector<LabelMeshOutcome> labels;

  times.start("Tiling");
  progress.start(stageIndex("Tiling")); // label by label
  for (std::size_t n = 0; n < extents.size(); ++n)
  {
    const LabelExtent& extent = extents[n];
    const auto labelBegan = Clock::now();
    LabelMeshOutcome outcome;
    outcome.label = extent.label;
    outcome.voxels = extent.voxels;
    const LabelColor entry = colors.entry(extent.label);
    outcome.name = entry.name;
    auto record = [&]
    {
      outcome.seconds = secondsSince(labelBegan);
      labels.push_back(outcome);
      progress.update(static_cast<double>(n + 1) / static_cast<double>(extents.size()));
    };
    try
    {
      const MaskVolume::Pointer mask = cropLabelMask(volume, extent);
      if (refinement.any())
        refineMask(mask, refinement);
      if (settings.minimumComponentVolume > 0.0)
      {
        const SmallComponentRemoval removal = removeSmallComponents(mask, settings.minimumComponentVolume);
        outcome.removedComponents = removal.removedComponents;
        if (removal.removedComponents == removal.components)
        {
          // Specks only: dropped, not a failure (the option asks for exactly this).
          outcome.dropped = true;
          std::cerr << "SliceMesh: warning: label " << extent.label << " (" << entry.name << ") dropped: each of its "
                    << removal.components << " connected components is smaller than the minimum component volume "
                    << settings.minimumComponentVolume << " mm^3 (the largest is " << removal.largestComponentVolume
                    << " mm^3)" << std::endl;
        }
      }
      if (outcome.dropped)
      {
        record();
        continue;
      }
      // The same contour preparation and correspondence stage as the single-mesh path
      // (SliceMeshPipeline): bridging and intermediate sections apply to every label.
      const ContourStack prepared = maskContours(mask, settings.contours, settings.preparation);
      SectionStatistics sections;
      const ContourStack stack = insertIntermediateSections(prepared, settings.undersampling, &sections);
      for (const std::string& note : sections.notes)
        result.sections.notes.push_back("label " + std::to_string(extent.label) + " (" + entry.name + "): " + note);
      const SliceFrame frame = sliceFrameOf(mask);
      ReconstructionOptions options = settings.reconstruction;
      options.progress = nullptr;
      const TriangleMesh stackMesh = reconstructSurface(stack, options);
      if (stackMesh.triangles.empty())
        throw Error("the reconstruction produced no triangles");
      // Finished as in the single-mesh path, at the label mask's spacing.
      const auto spacing = mask->GetSpacing();
      const std::string who = "label " + std::to_string(extent.label) + " (" + entry.name + "): ";
      const FinishedSurface finished =
        finishAndMeasure(stackMesh, validateMesh(stackMesh), stack, settings.finishing,
                         { spacing[0], spacing[1], spacing[2] }, who, outcome.quality);
      outcome.validation = finished.validation;
      outcome.contourPoints = contourPoints(stack);
      const TriangleMesh physical = mapToPhysicalSpace(finished.mesh, frame, settings.coordinateSystem);

      MeshAttributes attributes;
      const std::array<unsigned char, 3> rgb{ entry.rgba[0], entry.rgba[1], entry.rgba[2] };
      attributes.cellLabels.assign(physical.triangles.size(), extent.label);
      attributes.cellColors.assign(physical.triangles.size(), rgb);
      attributes.structures.push_back({ extent.label, entry.name, entry.rgba });
      if (!multi.outputDirectory.empty())
      {
        outcome.path = (fs::path(multi.outputDirectory) / labelFileName(entry, width, extension)).string();
        try
        {
          writeMesh(physical, settings.coordinateSystem, outcome.path, attributes);
        }
        catch (const std::exception& e)
        {
          throw PipelineFailure(WriteFailed, e.what());
        }
      }
      const auto offset = static_cast<std::int32_t>(merged.points.size());
      merged.points.insert(merged.points.end(), physical.points.begin(), physical.points.end());
      for (const Triangle& t : physical.triangles)
        merged.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
      mergedAttributes.cellLabels.insert(mergedAttributes.cellLabels.end(), attributes.cellLabels.begin(),
                                         attributes.cellLabels.end());
      mergedAttributes.cellColors.insert(mergedAttributes.cellColors.end(), attributes.cellColors.begin(),
                                         attributes.cellColors.end());
      mergedAttributes.structures.push_back(attributes.structures.front());
      accumulate(result.validation, outcome.validation);
    }
    catch (const PipelineFailure&)
    {
      throw;
    }
    catch (const std::exception& e)
    {
      outcome.error = e.what();
      std::ostringstream failure;
      failure << "label " << extent.label << " (" << entry.name << "): " << e.what();
      failures.push_back(failure.str());
      std::cerr << "SliceMesh: error: " << failures.back() << std::endl;
    }
    record();
  }

  if (merged.triangles.empty() && failures.empty())
  {
    std::ostringstream message;
    message << "every label of '" << settings.inputVolume << "' is smaller than the minimum component volume "
            << settings.minimumComponentVolume << " mm^3; nothing to mesh";
    throw PipelineFailure(EmptySegmentation, message.str());
  }

  times.start("Writing");
  progress.start(stageIndex("Writing"));
  if (!merged.triangles.empty())
  {
    try
    {
      writeMesh(merged, settings.coordinateSystem, settings.outputModel, mergedAttributes);
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(WriteFailed, e.what());
    }
  }
  result.quality = combinedQuality(labels, result.validation, merged);
  if (!settings.snapshotFile.empty() && !merged.triangles.empty())
  {
    try
    {
      writeSnapshot(merged, mergedAttributes.cellColors, settings.snapshotFile);
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(WriteFailed, e.what());
    }
  }
  progress.end();
  result.seconds = secondsSince(began);
  result.quality.stageSeconds = times.seconds();
  if (!settings.reportFile.empty())
  {
    try
    {
      writeQualityReport(settings.reportFile, settings.inputVolume, settings.outputModel, result.validation,
                         result.quality, result.seconds, labels);
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(WriteFailed, e.what());
    }
  }
  if (outcomes)
    outcomes->insert(outcomes->end(), labels.begin(), labels.end());
  if (!failures.empty())
  {
    std::ostringstream message;
    message << failures.size() << " of " << extents.size() << " labels failed; the others were written. First: "
            << failures.front();
    throw PipelineFailure(MeshingFailed, message.str());
  }
  return result;
}

} // namespace slicemesh::cli

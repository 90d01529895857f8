#include "SliceMeshPipeline.h"

#include "ColorTable.h"
#include "ContourRepair.h"
#include "Contours/ContourStacking.h"
#include "Core/ParallelFor.h"
#include "Core/PlanarGeometry.h"
#include "LabelIndex.h"
#include "MaskMeshing.h"
#include "MeshSnapshot.h"
#include "Measures/MeshComponents.h"
#include "NiftiOrientation.h"
#include "SegmentationFile.h"
#include "SmallComponentRemoval.h"
#include "StructureSet.h"
#include "StoredVolume.h"
#include "VolumeReader.h"
#include "VolumeSegmentation.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace slicemesh::cli
{
namespace
{

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

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

/** Throws WriteFailed unless `folder` exists (or, with `create`, can be made) and a file can be
 *  made in it: probed with a file of our own, since access() says yes to root on any folder. */
void requireWritableFolder(const fs::path& folder, bool create, const std::string& what)
{
  if (create && !fs::is_directory(folder))
  {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error)
      throw PipelineFailure(WriteFailed, "cannot create the output folder '" + folder.string() + "': " + error.message());
  }
  if (!fs::is_directory(folder))
    throw PipelineFailure(WriteFailed, what + ": folder '" + folder.string() + "' does not exist");
  std::string probe = (folder / ".SliceMesh-probe-XXXXXX").string();
  const int descriptor = ::mkstemp(probe.data());
  if (descriptor < 0)
  {
    const int error = errno;
    throw PipelineFailure(WriteFailed,
                          what + ": folder '" + folder.string() + "' is not writable (" + std::strerror(error) + ")");
  }
  ::close(descriptor);
  ::unlink(probe.c_str());
}

/** Everything that can fail without reading the input, checked before any work so that such a
 *  run writes nothing. */
ColorTable checkBeforeWork(const PipelineSettings& settings)
{
  const fs::path output(settings.outputModel);
  requireWritableFolder(output.has_parent_path() ? output.parent_path() : ".", false,
                        "cannot write mesh '" + settings.outputModel + "'");
  if ((settings.multiLabel.enabled || settings.contours.enabled()) && !settings.multiLabel.outputDirectory.empty())
    requireWritableFolder(settings.multiLabel.outputDirectory, true,
                          std::string("cannot write the ") + (settings.contours.enabled() ? "ROI" : "label") +
                            " meshes into '" + settings.multiLabel.outputDirectory + "'");
  std::string reason;
  if (!settings.snapshotFile.empty() && !snapshotAvailable(&reason))
    throw PipelineFailure(WriteFailed, "cannot render snapshot '" + settings.snapshotFile + "': " + reason);
  if (settings.multiLabel.enabled && !settings.multiLabel.colorTable.empty())
    return guarded(BadArguments, [&] { return ColorTable::read(settings.multiLabel.colorTable); });
  return {};
}

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
std::string who(const Structure& s, const std::string& noun)
{
  return noun.empty() ? std::string() : noun + " " + std::to_string(s.report.label) + " (" + s.report.name + "): ";
}

/** The single mask of a one-mesh run, after --minimumComponentVolume. */
Structure maskStructure(StoredVolume volume, const PipelineSettings& settings)
{
  Structure s;
  s.mask = guarded(EmptySegmentation, [&] { return segmentStoredVolume(std::move(volume), settings.segmentation); });
  if (settings.minimumComponentVolume > 0.0)
  {
    const SmallComponentRemoval removal =
      guarded(MeshingFailed, [&] { return removeSmallComponents(s.mask, settings.minimumComponentVolume); });
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
  return s;
}

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
 *  pass over the volume finds them all. */
std::vector<LabelSource> labelMapSources(const StoredVolume& volume, const ColorTable& colors)
{
  std::vector<LabelSource> sources;
  const auto index = [&] { return std::visit([](const auto& image) { return indexLabels(image.GetPointer()); }, volume); };
  for (const LabelExtent& e : guarded(EmptySegmentation, index))
  {
    const LabelColor entry = colors.entry(e.label);
    sources.push_back({ volume, e, e.label, entry.name, entry.rgba });
  }
  return sources;
}

/** Every segment of a segmentation file, in the file's order, named and coloured by the file; one
 *  pass over each layer finds them all. A segment without voxels keeps an empty extent. */
std::vector<LabelSource> segmentSources(const SegmentationFile& file, const std::string& path)
{
  std::vector<std::vector<LabelExtent>> layerExtents;
  for (const ScalarVolume::Pointer& layer : file.layers)
  {
    try
    {
      layerExtents.push_back(indexLabels(layer));
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(UnreadableInput, path + ": " + e.what());
    }
  }
  std::vector<LabelSource> sources;
  for (const SegmentationFile::Segment& segment : file.segments)
  {
    LabelSource source{ file.layers[segment.layer], {}, segment.number, segment.name, segment.rgba };
    source.extent.label = segment.labelValue;
    for (const LabelExtent& e : layerExtents[segment.layer])
      if (e.label == segment.labelValue)
        source.extent = e;
    sources.push_back(source);
  }
  if (std::none_of(sources.begin(), sources.end(), [](const LabelSource& s) { return s.extent.voxels > 0; }))
    throw PipelineFailure(EmptySegmentation, path + ": every segment of the " + file.format + " is empty; nothing to mesh");
  return sources;
}

std::string lowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/** One structure per source asked for (by number: label values or segment numbers; by name, any
 *  case; neither: all), each a mask cropped to its box. An empty source (a segment without voxels)
 *  is reported and dropped. */
std::vector<Structure> labelStructures(std::vector<LabelSource> sources, const std::vector<int>& numbers,
                                       const std::vector<std::string>& names, bool segments,
                                       const PipelineSettings& settings)
{
  if (!numbers.empty() || !names.empty())
  {
    std::set<int> wanted(numbers.begin(), numbers.end());
    std::set<std::string> wantedNames;
    for (const std::string& name : names)
      wantedNames.insert(lowerCase(name));
    std::vector<LabelSource> chosen;
    std::set<std::string> foundNames; // several labels may share a name: each is picked
    for (const LabelSource& source : sources)
    {
      const bool byNumber = wanted.erase(source.number) > 0;
      const bool byName = wantedNames.count(lowerCase(source.name)) > 0;
      if (byName)
        foundNames.insert(lowerCase(source.name));
      if (byNumber || byName)
        chosen.push_back(source);
    }
    for (const std::string& name : foundNames)
      wantedNames.erase(name);
    if (!wanted.empty() || !wantedNames.empty())
    {
      std::ostringstream message;
      message << settings.inputVolume;
      if (!wanted.empty())
      {
        message << (segments ? ": no segment numbered" : ": no voxel has label");
        for (int label : wanted)
          message << " " << label;
      }
      else
      {
        message << (segments ? ": no segment named" : ": no label named");
        for (const std::string& name : names)
          if (wantedNames.count(lowerCase(name)))
            message << " '" << name << "'";
      }
      if (segments || wanted.empty())
      {
        constexpr std::size_t listed = 20; // enough to spot a misspelling, short enough for one line
        message << (segments ? " (its segments:" : " (its labels:");
        for (std::size_t n = 0; n < std::min(sources.size(), listed); ++n)
          message << (n ? ", " : " ") << sources[n].number << " " << sources[n].name;
        if (sources.size() > listed)
          message << ", ... " << sources.size() << " in all";
        message << ")";
      }
      else
        message << " (" << sources.size() << " labels present)";
      throw PipelineFailure(EmptySegmentation, message.str());
    }
    sources = chosen;
  }
  if (sources.empty())
    throw PipelineFailure(EmptySegmentation, settings.inputVolume + ": every voxel is 0; nothing to mesh");
  if (!settings.segmentation.refinement.seeds.empty())
    std::cerr << "SliceMesh: warning: seed points are ignored when meshing every label separately" << std::endl;
  MaskRefinementOptions refinement = settings.segmentation.refinement;
  refinement.seeds.clear();

  std::vector<Structure> structures(sources.size());
  for (std::size_t n = 0; n < sources.size(); ++n)
  {
    Structure& s = structures[n];
    const LabelSource& source = sources[n];
    s.report.label = source.number;
    s.report.name = source.name;
    s.report.voxels = source.extent.voxels;
    s.rgba = source.rgba;
    if (source.extent.voxels == 0)
    {
      // An empty segment is not a failure: the file says it exists, it has nothing to mesh.
      s.report.dropped = true;
      std::cerr << "SliceMesh: warning: segment " << source.number << " (" << source.name
                << ") is empty; no mesh" << std::endl;
      continue;
    }
    try
    {
      s.mask = std::visit([&](const auto& image) { return cropLabelMask(image.GetPointer(), source.extent); },
                          source.labelMap);
      if (refinement.any())
        refineMask(s.mask, refinement);
      if (settings.minimumComponentVolume > 0.0)
      {
        const SmallComponentRemoval removal = removeSmallComponents(s.mask, settings.minimumComponentVolume);
        s.report.removedComponents = removal.removedComponents;
        if (removal.removedComponents == removal.components)
        {
          // Specks only: dropped, not a failure (the option asks for exactly this).
          s.report.dropped = true;
          std::cerr << "SliceMesh: warning: label " << s.report.label << " (" << s.report.name << ") dropped: each of its "
                    << removal.components
                    << " connected components is smaller than the minimum component volume "
                    << settings.minimumComponentVolume << " mm^3 (the largest is " << removal.largestComponentVolume
                    << " mm^3)" << std::endl;
        }
      }
    }
    catch (const std::exception& e)
    {
      s.report.error = e.what();
    }
  }
  return structures;
}

/** One structure per ROI asked for (every ROI by default), in the file's order: its contours as a
 *  stack along the reference image's slice direction and spacing when they lie on its slices (else
 *  along their own normal, with one warning for the set), crossings and keyholes repaired. An ROI whose contours lie in
 *  one slice is one slice spacing thick, the usual spacing of the other ROIs. An ROI that cannot
 *  be stacked (no contours, no spacing known) carries its error; every fault is one warning line. */
std::vector<Structure> roiStructures(const StructureSet& set, const std::optional<VolumeGeometry>& reference,
                                     const PipelineSettings& settings)
{
  const std::vector<PlanarStructure> rois =
    guarded(EmptySegmentation, [&] { return chosenStructures(set, settings.contours.rois); });
  std::vector<Structure> structures(rois.size());
  ContourStackingOptions stacking;
  stacking.sliceNormal = set.sliceNormal;
  if (reference)
  {
    stacking.sliceNormal = reference->sliceDirection();
    stacking.expectedSliceSpacing = reference->spacing[2];
  }
  std::vector<double> spacings;
  auto stack = [&](std::size_t n)
  {
    try
    {
      structures[n].contours = stackContours(rois[n].contours, stacking);
      structures[n].report.error.clear();
      return true;
    }
    catch (const Error& e)
    {
      structures[n].report.error = e.what();
      return false;
    }
  };
  for (std::size_t n = 0; n < rois.size(); ++n)
  {
    Structure& s = structures[n];
    s.report.label = rois[n].number;
    s.report.name = rois[n].name;
    s.rgba = { rois[n].rgb[0], rois[n].rgb[1], rois[n].rgb[2], 255 };
    for (const std::string& note : rois[n].notes)
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << oneLine(note) << std::endl;
    if (rois[n].contours.empty())
      s.report.error = "has no contours";
    else if (stack(n) && s.contours.stack.slices.size() > 1)
      spacings.push_back(s.contours.stack.sliceSpacing);
  }
  // An ROI in one slice gets the set's usual spacing as its thickness.
  stacking.fallbackSliceSpacing = median(spacings, 0.0);
  for (std::size_t n = 0; n < rois.size(); ++n)
    if (!structures[n].report.error.empty() && !rois[n].contours.empty() && stacking.fallbackSliceSpacing > 0.0)
      stack(n);
  // Contours off the image's slices are a mismatch of the whole set as a rule: one line for all.
  std::string offSlices;
  double largestDeviation = 0.0;
  for (const Structure& s : structures)
    if (s.report.error.empty() && s.contours.normalDeviationDegrees && !s.contours.givenNormalUsed)
    {
      offSlices += (offSlices.empty() ? "" : ", ") + std::to_string(s.report.label) + " (" + s.report.name + ")";
      largestDeviation = std::max(largestDeviation, *s.contours.normalDeviationDegrees);
    }
  if (!offSlices.empty())
  {
    std::ostringstream warning;
    warning.precision(3);
    warning << "the contours of ROI " << offSlices << " are not on the slices of '"
            << (reference ? settings.contours.referenceImage : settings.contours.path) << "': their slice normal is up to "
            << largestDeviation << " degrees from its slice direction (" << stacking.maxNormalDeviationDegrees
            << " allowed); each is stacked along its contours' own normal";
    std::cerr << "SliceMesh: warning: " << oneLine(warning.str()) << std::endl;
  }
  for (Structure& s : structures)
  {
    if (!s.report.error.empty())
      continue;
    std::size_t filled = 0;
    for (const Slice& slice : s.contours.stack.slices)
      filled += slice.contours.empty() ? 0 : 1;
    if (filled == 1 && settings.meshing.reconstruction.capPlacement == CapPlacement::AtSlice)
    {
      s.report.error = "all its contours lie in one slice, which has no thickness with the caps at the slice "
                       "(--capPlacement AtSlice)";
      continue;
    }
    ContourRepairReport repair;
    s.contours.stack = repairContours(s.contours.stack, settings.contours.repair, &repair);
    if (repair.any()) // a keyhole's perimeter is not its contours'
    {
      const double pointSpacing = automaticPointSpacing(s.contours.stack);
      s.contours.spacing[0] = s.contours.spacing[1] = s.contours.frame.spacing[0] = s.contours.frame.spacing[1] =
        pointSpacing;
    }
    for (const std::string& note : s.contours.notes)
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << oneLine(note) << std::endl;
    if (repair.any())
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << repair.summary(settings.contours.repair.channelWidth)
                << std::endl;
  }
  return structures;
}

std::size_t contourPoints(const ContourStack& stack)
{
  std::size_t points = 0;
  for (const Slice& slice : stack.slices)
    for (const Polygon2& contour : slice.contours)
      points += contour.size();
  return points;
}

/** The run's figures of one finished structure, for the summary line and the report. */
RunQuality runQualityOf(const MeshedContours& m)
{
  RunQuality quality;
  quality.shape = m.measures.shape;
  quality.dirichlet = m.measures.dirichlet;
  quality.genus = m.measures.genus;
  quality.pointSpacing = m.measures.pointSpacing;
  quality.sliceSpacing = m.measures.sliceSpacing;
  const ContourPreparationOptions& contours = m.options.contours;
  quality.contourPreparation = contours.mode == ContourPreparation::Smoothed ? "Smoothed" : "Traced";
  quality.capPlacement =
    m.options.reconstruction.capPlacement == CapPlacement::AtSlice ? "AtSlice" : "HalfSliceBeyond";
  quality.contourPointSpacing = contours.pointSpacing;
  quality.contourSmoothingMaxShift = contours.mode == ContourPreparation::Smoothed ? contours.smoothingMaxShift : 0.0;
  quality.wallRowHeight = m.reconstruction.wallRowHeight;
  quality.steinerSpacing = m.reconstruction.steinerSpacing;
  const SurfaceFinishingOptions& finishing = m.options.finishing;
  quality.requestedFinish = finishName(finishing.finish);
  quality.finish = finishName(m.surface.finish);
  quality.fallback = m.surface.fallback;
  quality.smallPiecesRemeshed = m.surface.smallPiecesRemeshed;
  quality.smallPiecesAsTiled = m.surface.smallPiecesAsTiled;
  quality.unsmoothedVertices = m.surface.unsmoothedVertices;
  quality.trianglesKeptTiled = m.surface.trianglesKeptTiled;
  quality.piecesByFinish = m.surface.piecesByFinish;
  if (finishing.finish == SurfaceFinish::Remeshed)
    quality.targetEdgeLength = finishing.remeshing.targetEdgeLength;
  if (finishing.finish != SurfaceFinish::Tiled)
  {
    quality.smoothingIterations = finishing.smoothing.iterations;
    quality.smoothingPassBand = finishing.smoothing.passBand;
    quality.smoothingMaxDisplacement = finishing.smoothing.maxDisplacement;
  }
  return quality;
}

/** "037_Hippocampus_L.vtp": the value zero-padded to sort in label order, then the safe name. */
std::string labelFileName(const Structure& s, int width, const std::string& extension)
{
  char value[32];
  std::snprintf(value, sizeof(value), "%0*d", width, s.report.label);
  return std::string(value) + "_" + safeFileName(s.report.name) + extension;
}

} // namespace

std::string oneLine(std::string text)
{
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
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

PipelineResult runPipeline(const PipelineSettings& settings, ProgressReporter& progress,
                           std::vector<LabelReport>* labels)
{
  const auto began = Clock::now();
  const bool fromContours = settings.contours.enabled();
  // A segmentation file (.seg.nrrd, DICOM SEG) names its structures: one mesh per segment.
  const bool segmentationInput = !fromContours && settings.segmentation.kind != InputKind::Grayscale &&
                                 segmentationFormatOf(settings.inputVolume) != SegmentationFormat::None;
  const bool perLabel = settings.multiLabel.enabled || fromContours || segmentationInput; // one mesh per structure
  const std::string noun = fromContours ? "ROI" : perLabel ? "label" : "";
  const std::string input = fromContours ? settings.contours.path : settings.inputVolume;
  const ColorTable colors = checkBeforeWork(settings);
  StageTimes times;
  auto startStage = [&](Stage stage)
  {
    times.start(pipelineStages()[stage].name);
    progress.start(stage);
  };

  startStage(Reading);
  StoredVolume volume; // as its file stores it: a label map of bytes takes a byte a voxel
  SegmentationFile segmentation;
  StructureSet structureSet;
  std::optional<VolumeGeometry> referenceImage;
  if (fromContours)
  {
    structureSet = guarded(UnreadableInput, [&] { return readStructureSet(settings.contours.path, settings.contours.kind); });
    if (!settings.contours.referenceImage.empty())
      referenceImage = guarded(UnreadableInput, [&] { return readVolumeGeometry(settings.contours.referenceImage); });
  }
  else if (segmentationInput)
  {
    segmentation = guarded(UnreadableInput, [&] { return readSegmentationFile(settings.inputVolume); });
    if (!settings.multiLabel.colorTable.empty())
      std::cerr << "SliceMesh: warning: --colorTable is not used: the segments' names and colours come from '"
                << settings.inputVolume << "'" << std::endl;
  }
  else
  {
    volume = guarded(UnreadableInput, [&] { return readStoredVolume(settings.inputVolume); });
    if (const auto warning = niftiOrientationWarning(settings.inputVolume, imageOf(volume)))
      std::cerr << "SliceMesh: warning: " << *warning << std::endl;
  }

  startStage(Segmentation);
  std::vector<Structure> structures;
  std::vector<std::string> failures;
  if (fromContours)
    structures = roiStructures(structureSet, referenceImage, settings);
  else if (segmentationInput)
  {
    // --label picks one segment as --labels does.
    std::vector<int> picked = settings.multiLabel.labels;
    if (picked.empty() && settings.multiLabel.labelNames.empty() && settings.segmentation.label)
      picked.push_back(*settings.segmentation.label);
    structures = labelStructures(segmentSources(segmentation, settings.inputVolume), picked,
                                 settings.multiLabel.labelNames, true, settings);
  }
  else if (perLabel)
    structures = labelStructures(labelMapSources(volume, colors), settings.multiLabel.labels,
                                 settings.multiLabel.labelNames, false, settings);
  else
    structures.push_back(maskStructure(std::move(volume), settings));
  // The masks are cut: the volume (or the segmentation's layers) is no longer needed.
  volume = StoredVolume();
  segmentation.layers.clear();
  for (const Structure& s : structures)
    if (!s.report.error.empty())
    {
      failures.push_back(who(s, noun) + s.report.error);
      std::cerr << "SliceMesh: error: " << failures.back() << std::endl;
    }

  // Every structure through one stage, then the next: each stage is reported once, its progress
  // structure by structure. Structures run side by side (each in its own slot, so the output does
  // not depend on the threads); the largest structure also gets them for its own work. In a
  // one-mesh run a failure ends the run with the stage's exit code; in a multi-label run it ends
  // only its label, reported on stderr in label order.
  const unsigned int threads = threadCount(settings.threads);
  const unsigned int outerThreads = structures.size() > 1 ? threads : 1;
  std::mutex progressLock;
  auto eachStructure = [&](ExitCode code, const std::function<void(Structure&, const std::function<void(double)>&)>& step)
  {
    const double count = static_cast<double>(structures.size());
    std::size_t done = 0;
    std::vector<std::string> errors(structures.size());
    parallelFor(structures.size(), outerThreads,
                [&](std::size_t n)
                {
                  Structure& s = structures[n];
                  if (s.live())
                  {
                    const auto stepBegan = Clock::now();
                    // Within-stage fractions only where one structure runs at a time: monotonic.
                    std::function<void(double)> fraction;
                    if (outerThreads == 1)
                      fraction = [&progress, n, count](double f) { progress.update((static_cast<double>(n) + f) / count); };
                    if (!perLabel)
                      guarded(code, [&] { step(s, fraction); });
                    else
                    {
                      try
                      {
                        step(s, fraction);
                      }
                      catch (const std::exception& e)
                      {
                        s.report.error = e.what();
                        errors[n] = who(s, noun) + e.what();
                      }
                    }
                    s.report.seconds += std::chrono::duration<double>(Clock::now() - stepBegan).count();
                  }
                  const std::lock_guard<std::mutex> lock(progressLock);
                  progress.update(static_cast<double>(++done) / count);
                });
    for (const std::string& error : errors)
      if (!error.empty())
      {
        failures.push_back(error);
        std::cerr << "SliceMesh: error: " << error << std::endl;
      }
  };

  startStage(Contours);
  eachStructure(MeshingFailed,
                [&](Structure& s, const std::function<void(double)>&)
                {
                  if (s.mask)
                  {
                    s.meshing = startMaskMeshing(s.mask, settings.meshing, settings.contourSmoothingSigma);
                    // Traced: the mask's voxels go, its frame stays to place the mesh.
                    s.contours.frame = sliceFrameOf(s.mask);
                    s.mask = nullptr;
                  }
                  else
                  {
                    // Planning-system contours are irregularly spaced: resampled (keeping their
                    // area) to the ROI's point spacing unless one was asked for.
                    MeshingOptions options = settings.meshing;
                    if (!(options.contours.pointSpacing > 0.0))
                      options.contours.pointSpacing = s.contours.spacing[0];
                    s.meshing = startMeshing(s.contours.stack, options, s.contours.spacing);
                  }
                  runMeshingStage(MeshingStage::Preparation, s.meshing);
                  if (!perLabel && contourPoints(s.meshing.stack) == 0)
                    throw PipelineFailure(EmptySegmentation,
                                          "the segmentation of '" + settings.inputVolume + "' has no contours");
                });
  // The structure holding most of the contour points (a BODY among organs, the one label of a
  // one-label run) would keep one thread busy long after the rest are done: it gets the threads for
  // the work inside it. The others run one thread each, side by side.
  std::size_t allPoints = 0;
  for (const Structure& s : structures)
    allPoints += s.live() ? contourPoints(s.meshing.stack) : 0;
  for (Structure& s : structures)
    if (s.live())
      s.meshing.options.threads = 2 * contourPoints(s.meshing.stack) > allPoints ? threads : 1;
  PipelineResult result;
  startStage(Correspondence);
  eachStructure(MeshingFailed, [&](Structure& s, const std::function<void(double)>& fraction)
                { runMeshingStage(MeshingStage::Correspondence, s.meshing, fraction); });
  for (const Structure& s : structures) // in label order, after the structures ran side by side
    if (s.live())
      for (const std::string& note : s.meshing.sections.notes)
        result.sections.notes.push_back(who(s, noun) + note);
  for (const auto& [stage, meshingStage] : { std::pair{ Tiling, MeshingStage::Tiling },
                                             std::pair{ Validation, MeshingStage::Validation },
                                             std::pair{ Finishing, MeshingStage::Finishing } })
  {
    startStage(stage);
    eachStructure(MeshingFailed,
                  [&, meshingStage = meshingStage](Structure& s, const std::function<void(double)>& fraction)
                  {
                    runMeshingStage(meshingStage, s.meshing, fraction);
                    // Finished and measured: the tiling is not held while the next structures and
                    // the writing run.
                    if (meshingStage == MeshingStage::Finishing)
                      s.meshing.tiling = TriangleMesh();
                  });
  }

  // From here on each mesh is the finished one: what is written, pictured and reported (only the
  // Dirichlet energy stays the tiling's).
  startStage(Writing);
  // The output model: the structures' meshes in physical space, in label order. Each is appended
  // and released as it is done, so that the meshes are not held twice (apart and merged).
  TriangleMesh merged;
  MeshAttributes mergedAttributes;
  std::vector<LabelReport> reports;
  std::vector<MeshValidation> validations;
  const fs::path output(settings.outputModel);
  const int width = perLabel && std::any_of(structures.begin(), structures.end(),
                                            [](const Structure& s) { return s.report.label >= 1000; })
                      ? 0
                      : 3;
  for (Structure& s : structures)
  {
    if (s.live())
    {
      const FinishedSurface& surface = s.meshing.surface;
      s.report.validation = surface.validation;
      s.report.quality = runQualityOf(s.meshing);
      s.report.contourPoints = contourPoints(s.meshing.stack);
      if (!surface.fallback.empty())
        std::cerr << "SliceMesh: warning: " << who(s, noun) << "surface finishing: " << oneLine(surface.fallback)
                  << std::endl;
      TriangleMesh physical = guarded(WriteFailed, [&]
                           { return mapToPhysicalSpace(surface.mesh, s.frame(), settings.coordinateSystem); });
      s.meshing.surface.mesh = TriangleMesh(); // its physical copy is what is written
      validations.push_back(surface.validation);
      if (perLabel)
      {
        MeshAttributes attributes;
        const std::array<unsigned char, 3> rgb{ s.rgba[0], s.rgba[1], s.rgba[2] };
        attributes.cellLabels.assign(physical.triangles.size(), s.report.label);
        attributes.cellColors.assign(physical.triangles.size(), rgb);
        attributes.structures.push_back({ s.report.label, s.report.name, s.rgba });
        if (!settings.multiLabel.outputDirectory.empty())
        {
          s.report.path = (fs::path(settings.multiLabel.outputDirectory) /
                           labelFileName(s, width, output.extension().string())).string();
          guarded(WriteFailed, [&] { writeMesh(physical, settings.coordinateSystem, s.report.path, attributes); });
        }
        mergedAttributes.cellLabels.insert(mergedAttributes.cellLabels.end(), attributes.cellLabels.begin(),
                                           attributes.cellLabels.end());
        mergedAttributes.cellColors.insert(mergedAttributes.cellColors.end(), attributes.cellColors.begin(),
                                           attributes.cellColors.end());
        mergedAttributes.structures.push_back(attributes.structures.front());
      }
      if (merged.points.empty())
        merged = std::move(physical); // the same as appending it to nothing, without a copy
      else
        appendMesh(merged, physical);
    }
    reports.push_back(s.report);
  }
  if (merged.triangles.empty() && failures.empty())
  {
    std::ostringstream message;
    message << "every label of '" << settings.inputVolume << "' is smaller than the minimum component volume "
            << settings.minimumComponentVolume << " mm^3; nothing to mesh";
    throw PipelineFailure(EmptySegmentation, message.str());
  }
  if (!merged.triangles.empty())
    guarded(WriteFailed,
            [&]
            {
              if (perLabel)
                writeMesh(merged, settings.coordinateSystem, settings.outputModel, mergedAttributes);
              else
                writeMesh(merged, settings.coordinateSystem, settings.outputModel);
            });
  // Neighbouring labels touch by design: each label's mesh is checked on its own, not against the others.
  result.validation = joinedValidation(validations, 0);
  if (perLabel)
    result.quality = combinedQuality(reports, result.validation, merged);
  else
  {
    result.quality = structures.front().report.quality;
    result.validation = structures.front().report.validation;
  }
  if (!settings.snapshotFile.empty() && !merged.triangles.empty())
    guarded(WriteFailed,
            [&]
            {
              if (perLabel)
                writeSnapshot(merged, mergedAttributes.cellColors, settings.snapshotFile);
              else
                writeSnapshot(merged, settings.snapshotFile);
            });
  progress.end();

  result.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  result.quality.stageSeconds = times.seconds();
  if (!settings.reportFile.empty())
    guarded(WriteFailed,
            [&]
            {
              writeQualityReport(settings.reportFile, input, settings.outputModel, result.validation,
                                 result.quality, result.seconds, perLabel ? reports : std::vector<LabelReport>{});
            });
  if (labels)
    labels->insert(labels->end(), reports.begin(), reports.end());
  if (!failures.empty())
  {
    std::ostringstream message;
    message << failures.size() << " of " << structures.size() << " " << noun << "s failed; "
            << (merged.triangles.empty() ? "nothing was written" : "the others were written") << ". First: "
            << failures.front();
    throw PipelineFailure(MeshingFailed, message.str());
  }
  return result;
}

} // namespace slicemesh::cli

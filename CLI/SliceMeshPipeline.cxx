#include "SliceMeshPipeline.h"

#include "Core/Determinant3.h"

#include "DistinctFiles.h"
#include "LengthLimits.h"
#include "MadeFolders.h"
#include "PipelineStep.h"
#include "PipelineStructures.h"

#include "Core/Lowercase.h"
#include "Core/ParallelFor.h"
#include "FileReplacement.h"
#include "Finishing/SurfaceSmoothing.h"
#include "MaskMeshing.h"
#include "MemoryBudget.h"
#include "MeshSnapshot.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "NiftiOrientation.h"
#include "SegmentationFile.h"
#include "StructureSet.h"
#include "StoredVolume.h"
#include "VolumeReader.h"
#include "VolumeSegmentation.h"
#include "itkMetaDataObject.h"
#include "vnl/vnl_matrix_fixed.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
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

/** Throws WriteFailed unless `folder` exists (or, given `made`, can be made) and a file can be
 *  made in it: probed with a file of our own, since access() says yes to root on any folder. */
void requireWritableFolder(const fs::path& folder, MadeFolders* made, const std::string& what)
{
  if (made && !fs::is_directory(folder))
  {
    std::error_code error;
    made->make(folder, error);
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
ColorTable checkBeforeWork(const PipelineSettings& settings, MadeFolders& made)
{
  // A malformed memory limit is a malformed value, said before the input is read rather than when
  // its memory is first checked.
  guarded(BadArguments, [] { return memoryLimitBytes(); });
  // The folder of the file each output replaces: a symbolic link's file's (writablePlace).
  auto folderOf = [](const std::string& file, const std::string& what)
  {
    const fs::path place = guarded(WriteFailed, [&] { return writablePlace(file, what); });
    return place.has_parent_path() ? place.parent_path() : fs::path(".");
  };
  requireWritableFolder(folderOf(settings.outputModel, "mesh"), nullptr, "cannot write mesh '" + settings.outputModel + "'");
  // The files written after the mesh: a missing folder must not cost the whole run.
  if (!settings.reportFile.empty())
    requireWritableFolder(folderOf(settings.reportFile, "report"), nullptr,
                          "cannot write report '" + settings.reportFile + "'");
  if (!settings.returnParameterFile.empty())
    requireWritableFolder(folderOf(settings.returnParameterFile, "the return-parameter file"), nullptr,
                          "cannot write the return-parameter file '" + settings.returnParameterFile + "'");
  if (!settings.snapshotFile.empty())
    requireWritableFolder(folderOf(settings.snapshotFile, "snapshot"), nullptr,
                          "cannot write snapshot '" + settings.snapshotFile + "'");
  if ((settings.multiLabel.enabled || settings.contours.enabled()) && !settings.multiLabel.outputDirectory.empty())
    requireWritableFolder(settings.multiLabel.outputDirectory, &made,
                          std::string("cannot write the ") + (settings.contours.enabled() ? "ROI" : "label") +
                            " meshes into '" + settings.multiLabel.outputDirectory + "'");
  std::string reason;
  if (!settings.snapshotFile.empty() && !snapshotAvailable(&reason))
    throw PipelineFailure(WriteFailed, "cannot render snapshot '" + settings.snapshotFile + "': " + reason);
  // Read in every run, not only where it names the labels: a wrong path is the user's mistake
  // whichever run it is given to.
  if (settings.multiLabel.colorTable.empty())
    return {};
  ColorTable table = guarded(BadArguments, [&] { return ColorTable::read(settings.multiLabel.colorTable); });
  // Said: which of a repeated value's names a mesh gets is the table's last line, maybe not the meant one.
  if (!table.repeatedLabels().empty())
  {
    const int first = table.repeatedLabels().front();
    std::cout << "SliceMesh: '" << settings.multiLabel.colorTable << "' lists " << table.repeatedLabels().size()
              << " value(s) more than once; each takes its last line (value " << first << ": '"
              << table.entry(first).name << "')" << std::endl;
  }
  return table;
}

/** Whether the frame's axes are not at right angles (a sheared grid, which NRRD and MetaImage can
 *  state): the stack frame's volumes, areas and angles are then not the physical mesh's. */
bool shears(const SliceFrame& frame)
{
  vnl_matrix_fixed<double, 3, 3> axes; // columns: the frame's axes
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      axes(row, column) = frame.direction[row][column];
  vnl_matrix_fixed<double, 3, 3> identity;
  identity.set_identity();
  // The axes' dot products against those of orthonormal axes.
  return (axes.transpose() * axes - identity).absolute_value_max() > 1e-6;
}

/** The validation's and the quality's measures of a structure, taken again on its mesh in physical
 *  space where its frame shears: the report says what the file holds. The voxels' volume too: a
 *  voxel of sheared axes holds |det| of the frame's unit axes times the product of its spacings
 *  (0.93 of it for a 15 degree gantry tilt), and the mesh, exact there, was said to fall 7-9% short. */
void measuredInPhysicalSpace(const TriangleMesh& physical, const SliceFrame& frame, MeshValidation& validation,
                             RunQuality& quality)
{
  const MeshValidation measured = validateMeshTopology(physical);
  validation.area = measured.area;
  validation.volume = measured.volume;
  validation.minAngleDegrees = measured.minAngleDegrees;
  validation.fractionAnglesBelow30 = measured.fractionAnglesBelow30;
  quality.shape = measureMeshQuality(physical);
  quality.targetVolume *= std::abs(determinant3(frame.direction));
}

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
  quality.contourSimplification = contours.simplificationTolerance;
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
  if (m.sections.sectionsInserted == 0 && m.options.finishing.finish != SurfaceFinish::Tiled)
    quality.targetVolume = m.targetVolume;
  quality.crossingRepairOperations = m.surface.crossingRepairOperations;
  quality.narrowTrianglesWidened = m.surface.narrowTrianglesWidened;
  quality.piecesByFinish = m.surface.piecesByFinish;
  if (finishing.finish == SurfaceFinish::Remeshed)
    quality.targetEdgeLength = finishing.remeshing.targetEdgeLength;
  if (finishing.finish != SurfaceFinish::Tiled)
  {
    quality.smoothingIterations = finishing.smoothing.iterations;
    quality.smoothingPassBand = finishing.smoothing.passBand;
    quality.smoothingMaxDisplacement = finishing.smoothing.maxDisplacement;
    quality.smoothingFeaturePairs = pairsBeforeFeaturesHeld(finishing.smoothing);
    quality.smoothingMaxDisplacementAwayFromFeatures = boundAwayFromFeatures(finishing.smoothing);
  }
  return quality;
}

/** The digits a run's structure files give their numbers: as many as the largest number has, at
 *  least three, so that a folder's files sort in the order of their numbers (the negative ones
 *  first, the nearest to zero first). A number of more digits once left every file unpadded, and
 *  a negative one had its sign take a digit's place ("0_Zero", "-3_Neg" beside "1000000_Million";
 *  "-05_Neg" beside "005_Five"). */
int structureFileDigits(const std::vector<Structure>& structures)
{
  std::size_t digits = 3;
  for (const Structure& s : structures)
    digits = std::max(digits, std::to_string(std::llabs(s.report.label)).size());
  return static_cast<int>(digits);
}

/** "037_Hippocampus_L.vtp", "-005_Lesion.vtp": the value's sign, its digits zero-padded to
 *  `digits` (structureFileDigits), then the safe name. */
std::string labelFileName(const Structure& s, int digits, const std::string& extension)
{
  const long long value = s.report.label;
  char number[32];
  std::snprintf(number, sizeof(number), "%s%0*lld", value < 0 ? "-" : "", digits, std::llabs(value));
  return std::string(number) + "_" + safeFileName(s.report.name) + extension;
}

/** The files in `folder` named as a structure's mesh is ("037_Name.vtp": a label number, an
 *  underscore, a mesh format's extension) that this run did not write: an earlier run's, with other
 *  labels or in another format (3D Slicer loading the folder would show both runs' meshes). */
std::vector<fs::path> otherStructureFiles(const fs::path& folder, const std::set<std::string>& written)
{
  const std::set<std::string> meshExtensions{ ".vtp", ".vtk", ".stl", ".ply", ".obj" };
  std::vector<fs::path> others;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
  {
    const std::string name = entry.path().filename().string();
    const std::size_t sign = name[0] == '-' ? 1 : 0; // a negative label's
    const std::size_t digits = name.find_first_not_of("0123456789", sign);
    const bool named = digits != std::string::npos && digits > sign && name[digits] == '_' &&
                       meshExtensions.count(lowercase(entry.path().extension().string())) > 0;
    if (named && entry.is_regular_file(error) && !written.count(name))
      others.push_back(entry.path());
  }
  std::sort(others.begin(), others.end());
  return others;
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
  // A usage error, before the input's voxels are read (of a detached header, its text is).
  requireDistinctFiles(settings);
  const bool fromContours = settings.contours.enabled();
  // A segmentation file (.seg.nrrd, DICOM SEG) names its structures: one mesh per segment.
  // (A DICOM file is asked of the DICOM plugin: one that cannot be loaded makes the input unreadable.)
  const bool segmentationInput =
    !fromContours && settings.segmentation.kind != InputKind::Grayscale &&
    guarded(UnreadableInput, [&] { return segmentationFormatOf(settings.inputVolume); }) != SegmentationFormat::None;
  const bool perLabel = settings.multiLabel.enabled || fromContours || segmentationInput; // one mesh per structure
  const std::string noun = fromContours ? "ROI" : perLabel ? "label" : "";
  const std::string input = fromContours ? settings.contours.path : settings.inputVolume;
  MadeFolders madeFolders;
  const ColorTable colors = checkBeforeWork(settings, madeFolders);
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
    {
      referenceImage = guarded(UnreadableInput, [&] { return readVolumeGeometry(settings.contours.referenceImage); });
      if (const auto warning = frameOfReferenceWarning(structureSet, *referenceImage, settings.contours))
        std::cerr << "SliceMesh: warning: " << *warning << std::endl;
    }
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
    std::string seriesChoice;
    if (itk::ExposeMetaData<std::string>(imageOf(volume)->GetMetaDataDictionary(), seriesChoiceKey, seriesChoice))
      std::cerr << "SliceMesh: warning: " << seriesChoice << std::endl;
  }

  startStage(Segmentation);
  std::vector<Structure> structures;
  std::vector<std::string> failures;
  std::string inputKindChoice;
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
  {
    // A volume given as a label map has its negative values meshed as labels, as --label does.
    const NegativeLabels negative =
      settings.segmentation.kind == InputKind::LabelMap ? NegativeLabels::Allowed : NegativeLabels::Refused;
    structures = labelStructures(labelMapSources(volume, colors, negative), settings.multiLabel.labels,
                                 settings.multiLabel.labelNames, false, settings);
  }
  else
    structures.push_back(maskStructure(std::move(volume), settings, &inputKindChoice));
  // The masks are cut: the volume (or the segmentation's layers) is no longer needed.
  volume = StoredVolume();
  segmentation.layers.clear();
  // Lengths too fine for the grid are refused before the meshing grows without bound.
  double smallestVoxelSide = std::numeric_limits<double>::infinity();
  for (const Structure& s : structures)
    if (s.live())
      for (unsigned int axis = 0; axis < 3; ++axis)
        smallestVoxelSide = std::min(smallestVoxelSide, s.mask ? s.mask->GetSpacing()[axis] : s.contours.spacing[axis]);
  if (std::isfinite(smallestVoxelSide))
    requireResolvableLengths(settings.meshing, smallestVoxelSide);
  const fs::path output(settings.outputModel);
  const int digits = structureFileDigits(structures);
  const bool structureFiles = perLabel && !settings.multiLabel.outputDirectory.empty();
  auto structureFile = [&](const Structure& s)
  { return (fs::path(settings.multiLabel.outputDirectory) / labelFileName(s, digits, output.extension().string())).string(); };
  // The structures' files are named now: one that is the input, or another output, is refused
  // before the meshing.
  if (structureFiles)
    for (const Structure& s : structures)
      if (s.live())
        requireDistinctStructureFile(settings, structureFile(s), who(s, noun));
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
                    MeshingOptions options = settings.meshing;
                    options.holdContours = false; // traced: a staircase, smoothed away
                    s.meshing = startMaskMeshing(s.mask, options, settings.contourSmoothingSigma);
                    // Traced: the mask's voxels go, its frame stays to place the mesh.
                    s.contours.frame = sliceFrameOf(s.mask);
                    s.mask = nullptr;
                  }
                  else
                  {
                    // Planning-system contours are irregularly spaced: resampled to the ROI's point
                    // spacing unless one was asked for (held: a target edge apart, keeping their
                    // corners; resolvedMeshingOptions).
                    MeshingOptions options = settings.meshing;
                    if (!options.holdContours && !(options.contours.pointSpacing > 0.0))
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
  result.inputKindChoice = inputKindChoice;
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
  auto attributesOf = [](const Structure& s, std::size_t triangles)
  {
    MeshAttributes attributes;
    attributes.cellLabels.assign(triangles, s.report.label);
    attributes.cellColors.assign(triangles, { s.rgba[0], s.rgba[1], s.rgba[2] });
    attributes.structures.push_back({ s.report.label, s.report.name, s.rgba });
    return attributes;
  };
  // Each structure's mesh is put in physical space side by side (each in its own slot); the physical
  // copy replaces the finished mesh, so no mesh is held twice.
  std::vector<TriangleMesh> physical(structures.size());
  parallelFor(structures.size(), outerThreads,
              [&](std::size_t n)
              {
                Structure& s = structures[n];
                if (!s.live())
                  return;
                physical[n] = guarded(WriteFailed, [&]
                                      { return mapToPhysicalSpace(s.meshing.surface.mesh, s.frame(), settings.coordinateSystem); });
                s.meshing.surface.mesh = TriangleMesh();
              });
  // The output model: the structures' meshes in label order, each appended and released in turn;
  // where each was appended is kept: its own file is written from its part of the model.
  TriangleMesh merged;
  MeshAttributes mergedAttributes;
  std::vector<LabelReport> reports;
  std::vector<MeshValidation> validations;
  std::vector<AppendedAt> appendedAt(structures.size() + 1);
  std::vector<std::size_t> shortOfVolume; // structures whose surface holds less than it was given (volumeShortfall)
  // At its size from the start: grown by doubling, the model was copied over and over (a whole-body
  // segmentation's, of millions of triangles, on one thread), and its spare room, never touched,
  // costs no memory.
  // A model of one structure is that structure's mesh, moved in without a copy.
  std::size_t mergedPoints = 0, mergedTriangles = 0, liveStructures = 0;
  for (std::size_t n = 0; n < structures.size(); ++n)
    if (structures[n].live())
    {
      mergedPoints += physical[n].points.size();
      mergedTriangles += physical[n].triangles.size();
      ++liveStructures;
    }
  if (liveStructures > 1)
  {
    merged.points.reserve(mergedPoints);
    merged.triangles.reserve(mergedTriangles);
  }
  for (std::size_t n = 0; n < structures.size(); ++n)
  {
    Structure& s = structures[n];
    appendedAt[n] = { merged.points.size(), merged.triangles.size() };
    if (s.live())
    {
      if (structureFiles)
        s.report.path = structureFile(s);
      const FinishedSurface& surface = s.meshing.surface;
      s.report.validation = surface.validation;
      s.report.quality = runQualityOf(s.meshing);
      if (shears(s.frame()))
        measuredInPhysicalSpace(physical[n], s.frame(), s.report.validation, s.report.quality);
      s.report.contourPoints = contourPoints(s.meshing.stack);
      if (!surface.fallback.empty())
        std::cerr << "SliceMesh: warning: " << who(s, noun) << "surface finishing: " << oneLine(surface.fallback)
                  << std::endl;
      if (const auto specks = perLabel ? std::nullopt : speckNoiseWarning(surface))
        std::cerr << "SliceMesh: warning: " << *specks << std::endl;
      if (volumeShortfall(s.report))
        shortOfVolume.push_back(n);
      validations.push_back(s.report.validation);
      if (perLabel)
      {
        const MeshAttributes attributes = attributesOf(s, physical[n].triangles.size());
        mergedAttributes.cellLabels.insert(mergedAttributes.cellLabels.end(), attributes.cellLabels.begin(),
                                           attributes.cellLabels.end());
        mergedAttributes.cellColors.insert(mergedAttributes.cellColors.end(), attributes.cellColors.begin(),
                                           attributes.cellColors.end());
        mergedAttributes.structures.push_back(attributes.structures.front());
      }
      if (liveStructures == 1)
        merged = std::move(physical[n]);
      else
        appendMesh(merged, physical[n]);
      physical[n] = TriangleMesh();
    }
    reports.push_back(s.report);
  }
  appendedAt[structures.size()] = { merged.points.size(), merged.triangles.size() };
  // On stdout: specks make most of these, as asked, and 3D Slicer marks a run that writes to
  // stderr as failing.
  if (!shortOfVolume.empty())
    std::cout << "SliceMesh: " << volumeShortfallWarning(structures, shortOfVolume, noun, fromContours) << std::endl;
  // One mesh per label asked for without a folder: said, since the help's "files" read as if they
  // were written anyway.
  if (perLabel && !structureFiles && structures.size() > 1)
    std::cout << "SliceMesh: the " << structures.size() << " " << noun << "s' meshes are in '" << settings.outputModel
              << "' alone (its Label array tells them apart); --outputDirectory also writes a file for each" << std::endl;
  if (merged.triangles.empty() && failures.empty())
  {
    std::ostringstream message;
    const bool everyOneEmpty = std::all_of(structures.begin(), structures.end(), [](const Structure& s)
                                           { return s.report.droppedBecause == "the segment is empty"; });
    if (fromContours)
      message << "no ROI of '" << input << "' has a closed contour; nothing to mesh";
    else if (everyOneEmpty)
      message << (structures.size() == 1 ? "the segment asked for, " : "every segment asked for, the first ")
              << structures.front().report.label << " (" << structures.front().report.name << "), holds no voxel in '"
              << settings.inputVolume << "'; nothing to mesh";
    else
      message << "every label of '" << settings.inputVolume << "' is smaller than the minimum component volume "
              << settings.minimumComponentVolume << " mm^3; nothing to mesh";
    throw PipelineFailure(EmptySegmentation, message.str());
  }
  // Neighbouring labels touch by design: each label's mesh is checked on its own, not against the others.
  result.validation = joinedValidation(validations, 0);
  // The merged model, the structures' own files and the whole model's triangle shapes side by side:
  // the merged model first (the largest task; written after the others, it ran alone at the end).
  // A failure is reported as when they were written one by one: the first structure's in label
  // order, then the merged model's (task 0 fails in slot structures.size(), task 1 in the next).
  // Each file is written to its temporary, and all are moved into place together once every one is
  // written (commitTogether): a file that cannot be written (a full disk) leaves every earlier file
  // as it was, where the files written before it had replaced theirs. Slot n holds structure n's
  // file, the last slot the merged model.
  std::vector<std::unique_ptr<FileReplacement>> written(structures.size() + 1);
  std::vector<std::exception_ptr> writeFailures(structures.size() + 2);
  parallelFor(structures.size() + 2, threads,
              [&](std::size_t task)
              {
                try
                {
                  if (task == 0)
                  {
                    if (!merged.triangles.empty())
                      written.back() = guarded(WriteFailed,
                                               [&]
                                               {
                                                 const MeshAttributes none;
                                                 return writeMeshUncommitted(merged, settings.coordinateSystem,
                                                                             settings.outputModel,
                                                                             perLabel ? mergedAttributes : none);
                                               });
                  }
                  else if (task == 1)
                  {
                    if (perLabel)
                      result.quality = combinedQuality(reports, result.validation, merged);
                  }
                  else if (structureFiles && structures[task - 2].live())
                  {
                    const std::size_t n = task - 2;
                    const Structure& s = structures[n];
                    const TriangleMesh own = appendedPart(merged, appendedAt[n], appendedAt[n + 1]);
                    written[n] = guarded(WriteFailed,
                                         [&]
                                         {
                                           return writeMeshUncommitted(own, settings.coordinateSystem, s.report.path,
                                                                       attributesOf(s, own.triangles.size()));
                                         });
                  }
                }
                catch (...)
                {
                  writeFailures[task < 2 ? structures.size() + task : task - 2] = std::current_exception();
                }
              });
  for (const std::exception_ptr& failure : writeFailures)
    if (failure)
      std::rethrow_exception(failure);
  guarded(WriteFailed, [&] { commitTogether(written); });
  // Said, not removed: the files are the user's, and may be wanted.
  if (structureFiles)
  {
    std::set<std::string> written, failed; // file names: of the meshes written, of those that failed
    for (const Structure& s : structures)
      if (s.live())
        written.insert(fs::path(s.report.path).filename().string());
      else if (!s.report.error.empty())
        failed.insert(labelFileName(s, digits, output.extension().string()));
    std::vector<fs::path> others = otherStructureFiles(settings.multiLabel.outputDirectory, written);
    // A file of a structure that failed here is an earlier run's mesh of it, not of another.
    const auto stale = std::stable_partition(others.begin(), others.end(), [&](const fs::path& file)
                                             { return failed.count(file.filename().string()) > 0; });
    const std::string folder = settings.multiLabel.outputDirectory;
    if (stale != others.begin())
      std::cerr << "SliceMesh: warning: '" << folder << "' still holds " << (stale - others.begin())
                << " mesh file(s) of " << noun << "s that failed in this run (first: "
                << others.front().filename().string() << "): an earlier run's, left as they were" << std::endl;
    if (stale != others.end())
      std::cerr << "SliceMesh: warning: '" << folder << "' also holds " << (others.end() - stale)
                << " mesh file(s) this run did not write (first: " << stale->filename().string()
                << "): an earlier run's, of other " << noun << "s or in another format" << std::endl;
  }
  if (!perLabel)
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
    // Each failure has had its error line: the count, not the first one's reason again.
    std::ostringstream message;
    message << failures.size() << " of " << structures.size() << " " << noun << "s failed; "
            << (merged.triangles.empty() ? "nothing was written" : "the others were written");
    if (merged.triangles.empty())
      throw PipelineFailure(MeshingFailed, message.str());
    throw PipelineFailure(MeshingFailed, message.str(), result);
  }
  madeFolders.keep();
  return result;
}

} // namespace slicemesh::cli

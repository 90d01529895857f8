// Argument handling and reporting around the pipeline: --xml first, then the table-driven parse,
// --help/--echo, progress, the summary line, return parameters and the exit code.
#include "ModuleEntryPoint.h"

#include "CommandLine.h"
#include "DicomFolder.h"
#include "ExitCodes.h"
#include "HelpText.h"
#include "ModuleDescription.h"
#include "ModuleXml.h"
#include "ReturnParameters.h"
#include "SegmentationArguments.h"
#include "SliceMeshPipeline.h"
#include "StructureSet.h"
#include "Core/ParallelFor.h"

#include "itkObject.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace
{

using namespace slicemesh;
using namespace slicemesh::cli;

int fail(ExitCode code, const std::string& message)
{
  std::cerr << "SliceMesh: error: " << oneLine(message) << std::endl;
  return code;
}

/** A DICOM folder of an image series and a segmentation (SEG) drawn on it: the segmentation is
 *  what is meant, as a structure set is. It was passed over, and the image thresholded. */
void useSegmentationOfFolder(PipelineSettings& settings, const DicomFolderContents& folder)
{
  if (folder.segmentations.empty())
    return;
  auto name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  if (folder.segmentations.size() > 1)
  {
    std::string names;
    for (const std::string& path : folder.segmentations)
      names += (names.empty() ? "" : ", ") + name(path);
    throw PipelineFailure(UnreadableInput, settings.inputVolume + " holds " + std::to_string(folder.segmentations.size()) +
                                             " segmentations (" + names + "): give the one to mesh as the input");
  }
  std::cerr << "SliceMesh: " << settings.inputVolume << " holds a segmentation, " << name(folder.segmentations.front())
            << ": its segments are meshed (to mesh the image series itself, give a folder without it)" << std::endl;
  settings.inputVolume = folder.segmentations.front();
}

/** A DICOM folder given as the input that holds a structure set, as a planning system exports a
 *  plan (the CT slices and the RTSTRUCT side by side): its ROIs are what is meant, stacked on the
 *  folder's image series. Two or more structure sets: which one is for the user to say. */
void useStructureSetOfFolder(PipelineSettings& settings)
{
  std::error_code ignored;
  if (!std::filesystem::is_directory(settings.inputVolume, ignored))
    return;
  const DicomFolderContents folder = dicomFolderContents(settings.inputVolume);
  auto name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  if (folder.structureSets.empty())
  {
    useSegmentationOfFolder(settings, folder);
    return;
  }
  if (folder.structureSets.size() > 1)
  {
    std::string names;
    for (const std::string& path : folder.structureSets)
      names += (names.empty() ? "" : ", ") + name(path);
    throw PipelineFailure(UnreadableInput, settings.inputVolume + " holds " + std::to_string(folder.structureSets.size()) +
                                             " structure sets (" + names +
                                             "): give the one to mesh with --inputContours, the folder beside it");
  }
  settings.contours.path = folder.structureSets.front();
  const bool series = folder.otherDicomFiles >= 2;
  if (series)
    settings.contours.referenceImage = settings.inputVolume;
  std::cerr << "SliceMesh: " << settings.inputVolume << " holds a structure set, " << name(settings.contours.path)
            << ": its ROIs are meshed" << (series ? ", stacked on the folder's image series" : "")
            << " (to mesh the image series itself, give a folder without the structure set)" << std::endl;
}

/** The structure set or contour file to mesh: --inputContours, else the input itself when
 *  --contourFormat names a kind or the file is detected as one, or the structure set of a DICOM
 *  folder; empty for a volume. An input volume given beside --inputContours is the image the
 *  contours were drawn on. */
void readContourArguments(const ParsedArguments& arguments, PipelineSettings& settings)
{
  const std::string& format = arguments.text("contourFormat");
  ContourInputSettings& contours = settings.contours;
  contours.kind = format == "RTSTRUCT"   ? ContourFileKind::RTStruct
                  : format == "PolyData" ? ContourFileKind::PolyData
                  : format == "JSON"     ? ContourFileKind::Json
                                         : ContourFileKind::Automatic;
  if (!arguments.text("inputContours").empty())
  {
    contours.path = arguments.text("inputContours");
    if (settings.inputVolume != contours.path)
      contours.referenceImage = settings.inputVolume;
  }
  else if (contours.kind != ContourFileKind::Automatic || detectContourFileKind(settings.inputVolume))
    contours.path = settings.inputVolume;
  else
    useStructureSetOfFolder(settings);
  std::istringstream rois(arguments.text("rois"));
  for (std::string roi; std::getline(rois, roi, ',');)
  {
    roi.erase(0, roi.find_first_not_of(" \t"));
    roi.erase(roi.find_last_not_of(" \t") + 1);
    if (!roi.empty())
      contours.rois.push_back(roi);
  }
  if (!contours.rois.empty() && !contours.enabled())
    std::cerr << "SliceMesh: warning: --rois is used only with a structure set or contour file; it has no effect"
              << std::endl;
  contours.repair.channelWidth = arguments.number("contourChannelWidth");
}

PipelineSettings settingsFrom(const ParsedArguments& arguments)
{
  PipelineSettings settings;
  settings.inputVolume = arguments.text("inputVolume");
  settings.outputModel = arguments.text("outputModel");
  readContourArguments(arguments, settings);

  const std::string& kind = arguments.text("inputKind");
  settings.segmentation.kind =
    kind == "LabelMap" ? InputKind::LabelMap : kind == "Grayscale" ? InputKind::Grayscale : InputKind::Automatic;
  // Label 0 is the background in every label map, so it stands for "every non-zero voxel".
  if (const long label = arguments.integer("label"); label != 0)
  {
    settings.segmentation.label = static_cast<int>(label);
  }
  if (arguments.text("thresholdMethod") == "Manual")
  {
    settings.segmentation.threshold = arguments.number("threshold");
  }
  else if (arguments.given("threshold") && arguments.number("threshold") != 0.0 &&
           settings.segmentation.kind != InputKind::LabelMap)
  {
    // Slicer passes every scalar (the default 0 included), so this cannot be an error; when a user
    // set a threshold, say why it has no effect.
    std::cerr << "SliceMesh: warning: --threshold is used only with --thresholdMethod Manual; using Otsu"
              << std::endl;
  }

  readSegmentationArguments(arguments, settings);
  settings.meshing.undersampling.correspondenceDistance = arguments.number("correspondenceDistance");
  settings.meshing.undersampling.bridgeNonOverlapping = arguments.flag("bridgeNonOverlapping");
  settings.meshing.undersampling.maxSliceSpacingFactor = arguments.number("maxSliceSpacingFactor");
  settings.meshing.undersampling.sectionOverlap = arguments.number("sectionOverlap");
  settings.meshing.undersampling.refineWeakOverlap = arguments.flag("refineWeakOverlap");
  const bool bridging =
    settings.meshing.undersampling.bridgeNonOverlapping && settings.meshing.undersampling.correspondenceDistance > 0.0;
  if (settings.meshing.undersampling.bridgeNonOverlapping && !bridging)
  {
    std::cerr << "SliceMesh: warning: --bridgeNonOverlapping needs --correspondenceDistance > 0; nothing is bridged"
              << std::endl;
  }
  // Slicer passes the default too: only a changed value that nothing reads is worth a word.
  if (!bridging && !settings.meshing.undersampling.refineWeakOverlap &&
      settings.meshing.undersampling.sectionOverlap != UndersamplingOptions().sectionOverlap)
  {
    std::cerr << "SliceMesh: warning: --sectionOverlap is used only with --bridgeNonOverlapping or "
                 "--refineWeakOverlap; it has no effect"
              << std::endl;
  }
  settings.minimumComponentVolume = arguments.number("minimumComponentVolume");
  settings.meshing.reconstruction.capPlacement =
    arguments.text("capPlacement") == "AtSlice" ? CapPlacement::AtSlice : CapPlacement::HalfSliceBeyond;
  settings.meshing.reconstruction.wallRowHeight = arguments.number("wallRowHeight");
  settings.meshing.reconstruction.minAngleDegrees = arguments.number("minimumAngle");
  settings.meshing.reconstruction.maxEdgeLength = arguments.number("maxEdgeLength");
  settings.meshing.reconstruction.planarTiling = arguments.flag("planarTiling");
  settings.coordinateSystem =
    arguments.text("coordinateSystem") == "RAS" ? CoordinateSystem::RAS : CoordinateSystem::LPS;
  settings.contourSmoothingSigma = arguments.number("contourSmoothingSigma");
  settings.meshing.contours.simplificationTolerance = arguments.number("contourSimplification");
  settings.meshing.contours.pointSpacing = arguments.number("contourPointSpacing");
  settings.meshing.holdContours = arguments.flag("holdContours");
  const std::string& preparation = arguments.text("contourPreparation");
  settings.meshing.contours.mode = preparation == "Smoothed" ? ContourPreparation::Smoothed
                                   : preparation == "Traced" ? ContourPreparation::Traced
                                                             : ContourPreparation::Automatic;
  settings.meshing.contours.smoothingIterations = static_cast<int>(arguments.integer("contourSmoothingIterations"));
  settings.meshing.contours.smoothingMaxShift = arguments.number("contourSmoothingMaxShift");
  const std::string& finish = arguments.text("surfaceFinish");
  settings.meshing.finishing.finish = finish == "Tiled"      ? SurfaceFinish::Tiled
                                      : finish == "Smoothed" ? SurfaceFinish::Smoothed
                                                             : SurfaceFinish::Remeshed;
  settings.meshing.finishing.remeshing.targetEdgeLength = arguments.number("targetEdgeLength"); // 0: automatic
  settings.meshing.finishing.smoothing.iterations = static_cast<int>(arguments.integer("surfaceSmoothingIterations"));
  settings.meshing.finishing.smoothing.passBand = arguments.number("surfaceSmoothingPassBand");
  // The XML's range is inclusive (it sets a GUI slider); the pass band must lie strictly inside it
  // (smoothSurface's precondition), so the ends are a usage error here, before any work.
  if (!(settings.meshing.finishing.smoothing.passBand > 0.0 && settings.meshing.finishing.smoothing.passBand < 1.0))
  {
    std::ostringstream message;
    message << "--surfaceSmoothingPassBand (Surface smoothing pass band): "
            << arguments.text("surfaceSmoothingPassBand")
            << " is outside the range 0 .. 1 (both excluded)";
    throw PipelineFailure(BadArguments, message.str());
  }
  settings.reportFile = arguments.text("report");
  settings.snapshotFile = arguments.text("snapshot");
  settings.returnParameterFile = arguments.returnParameterFile;
  settings.threads = static_cast<unsigned int>(arguments.integer("threads"));
  return settings;
}

/** "123.4 mm^3 (0.12 mL)". */
std::string volumeText(double mm3)
{
  return measureText(mm3, 1) + " mm^3 (" + measureText(mm3 / 1000.0, 2) + " mL)";
}

std::string summaryLine(const PipelineResult& result, const std::string& outputModel, bool eachStructure)
{
  const MeshValidation& v = result.validation;
  std::ostringstream line;
  line << "SliceMesh: " << v.triangles << " triangles, " << (v.closed() ? "closed" : "NOT closed") << ", volume "
       << volumeText(v.volume) << ", " << std::fixed << std::setprecision(2) << result.seconds << " s -> "
       << outputModel << "; "
       << qualitySummary(v, result.quality, eachStructure);
  return line.str();
}

/** "SliceMesh: ROI 2 (PTV): volume 123.4 mm^3 (0.12 mL), 2048 triangles, closed, genus 0 -> 002_PTV.vtp",
 *  or that it failed (its error line on stderr says why: the reason once). */
std::string roiLine(const LabelReport& roi)
{
  std::ostringstream line;
  line << "SliceMesh: ROI " << roi.label << " (" << roi.name << "): ";
  if (roi.dropped)
    line << "not meshed: " << roi.droppedBecause;
  else if (!roi.meshed())
    line << "failed (see its error line)";
  else
  {
    const MeshValidation& v = roi.validation;
    line << "volume " << volumeText(v.volume) << ", " << v.triangles << " triangles, " << (v.valid() ? "valid" : "NOT valid")
         << ", genus " << roi.quality.genus;
    if (!roi.path.empty())
      line << " -> " << roi.path;
  }
  return line.str();
}

/** How the ROI volumes count the end slices, once per run. */
std::string capLine(const PipelineSettings& settings)
{
  return settings.meshing.reconstruction.capPlacement == CapPlacement::AtSlice
           ? "SliceMesh: ROI volumes end at the first and last contours (--capPlacement AtSlice)"
           : "SliceMesh: ROI volumes include half a slice beyond the first and last contours, as planning systems "
             "count them (--capPlacement AtSlice ends them at the contours)";
}

ReturnValues returnValues(const PipelineResult& result, std::size_t structuresWritten)
{
  std::ostringstream volume, seconds;
  volume << std::setprecision(10) << result.validation.volume;
  seconds << std::setprecision(6) << result.seconds;
  return { { "triangles", std::to_string(result.validation.triangles) },
           { "volume", volume.str() },
           { "closed", result.validation.closed() ? "true" : "false" },
           { "seconds", seconds.str() },
           { "structuresWritten", std::to_string(structuresWritten) } };
}

} // namespace

int ModuleEntryPoint(int argc, char* argv[])
{
  // As GenerateCLP does: answer Slicer's discovery before anything else can get in the way.
  if (argc > 1 && std::string(argv[1]) == "--xml")
  {
    std::cout << moduleXml() << std::flush;
    return Success;
  }

  // ITK's warnings are multi-line console dumps (e.g. GDCM's "No Series were found" before the
  // reader's own error); the library functions report what matters through exceptions.
  itk::Object::GlobalWarningDisplayOff();

  try
  {
    const ModuleDescription module = parseModuleDescription(moduleXml());
    ParsedArguments arguments;
    try
    {
      arguments = parseCommandLine(module, std::vector<std::string>(argv + 1, argv + argc));
    }
    catch (const ArgumentError& e)
    {
      return fail(BadArguments, e.what());
    }
    if (arguments.xml)
    {
      std::cout << moduleXml() << std::flush;
      return Success;
    }
    if (arguments.help)
    {
      std::cout << helpText(module, "SliceMesh") << std::flush;
      return Success;
    }
    if (arguments.version)
    {
      std::cout << module.title << " " << module.version << std::endl;
      return Success;
    }
    if (arguments.echo)
    {
      std::cout << echoText(module, arguments) << std::flush;
    }

    // Slicer reads stdout through a pipe: tags then. A person at a terminal gets a bar on stderr instead.
    const bool stdoutIsTerminal = ::isatty(STDOUT_FILENO) == 1;
    const bool stderrIsTerminal = ::isatty(STDERR_FILENO) == 1;
    ProgressReporter progress(pipelineStages(), stdoutIsTerminal ? nullptr : &std::cout,
                              stderrIsTerminal ? &std::cerr : nullptr);

    PipelineResult result;
    std::vector<LabelReport> structures;
    std::size_t structuresWritten = 1;
    bool finished = false;
    try
    {
      const PipelineSettings settings = settingsFrom(arguments);
      // Work that asks for every core (the validation, the self-intersection test, TBB's threads in
      // CGAL) stays within --threads too.
      everyCoreLimit() = threadCount(settings.threads);
      const tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism, threadCount(settings.threads));
      auto printRois = [&]
      {
        if (!settings.contours.enabled() || structures.empty())
          return;
        for (const LabelReport& roi : structures)
          std::cout << roiLine(roi) << std::endl;
        std::cout << capLine(settings) << std::endl;
      };
      try
      {
        result = runPipeline(settings, progress, &structures);
      }
      catch (const PipelineFailure&)
      {
        progress.finish(false);
        finished = true;
        printRois(); // the ROIs that were written, and why the others were not
        throw;
      }
      progress.finish(true);
      printRois();
      if (!structures.empty())
        structuresWritten = static_cast<std::size_t>(
          std::count_if(structures.begin(), structures.end(), [](const LabelReport& s) { return s.meshed(); }));
    }
    catch (const PipelineFailure& e)
    {
      if (!finished)
        progress.finish(false);
      // Some structures written, others failed: Slicer still gets the values of what was written.
      if (e.written() && !arguments.returnParameterFile.empty())
      {
        const std::size_t written = static_cast<std::size_t>(
          std::count_if(structures.begin(), structures.end(), [](const LabelReport& s) { return s.meshed(); }));
        try
        {
          writeReturnParameters(arguments.returnParameterFile, returnValues(*e.written(), written));
        }
        catch (const Error& error)
        {
          std::cerr << "SliceMesh: error: " << oneLine(error.what()) << std::endl;
        }
      }
      return fail(e.code(), e.what());
    }

    for (const std::string& note : result.sections.notes)
    {
      std::cerr << "SliceMesh: warning: " << oneLine(note) << std::endl;
    }
    // On stdout: a note, not a warning (3D Slicer marks a run that writes to stderr as failing).
    if (!result.inputKindChoice.empty())
      std::cout << "SliceMesh: " << result.inputKindChoice << std::endl;
    std::cout << summaryLine(result, arguments.text("outputModel"), !structures.empty()) << std::endl;
    if (!arguments.returnParameterFile.empty())
    {
      try
      {
        writeReturnParameters(arguments.returnParameterFile, returnValues(result, structuresWritten));
      }
      catch (const Error& e)
      {
        return fail(WriteFailed, e.what());
      }
    }
    if (!result.validation.valid())
    {
      std::cerr << "SliceMesh: warning: the mesh was written but is not a valid closed surface: "
                << oneLine(result.validation.summary()) << std::endl;
      return InvalidMesh;
    }
    return Success;
  }
  catch (const std::exception& e)
  {
    return fail(InternalError, std::string("unexpected failure: ") + e.what());
  }
}

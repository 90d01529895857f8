#include "SegmentationArguments.h"

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>

namespace slicemesh::cli
{
namespace
{

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

/** The comma-separated items of --labels; none when it is empty (every label). An empty item
 *  ("1,,3", ",,,") is refused: it was read as no label at all, and ",,," as every label. */
std::vector<std::string> labelItems(const std::string& text)
{
  std::vector<std::string> items;
  if (text.empty())
    return items;
  for (std::size_t begin = 0;;)
  {
    const std::size_t comma = text.find(',', begin);
    items.push_back(text.substr(begin, comma - begin));
    if (items.back().find_first_not_of(" \t") == std::string::npos)
      throw ArgumentError("--labels: '" + text + "' has an empty item (give the labels to mesh, e.g. --labels 1,3, "
                          "or leave it empty for every label)");
    if (comma == std::string::npos)
      return items;
    begin = comma + 1;
  }
}

double toNumber(const std::string& text, const std::string& who)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw ArgumentError(who + ": '" + text + "' is not a number");
  return value;
}

/** Options of one input kind given with the other are refused, or (beside an explicit label map,
 *  where the grayscale options are plainly unused) said to have no effect: each was ignored without
 *  a word, and an MR meshed as a label map of its intensities. */
void checkInputKindOptions(const PipelineSettings& settings)
{
  const SegmentationOptions& segmentation = settings.segmentation;
  const std::string request = grayscaleRequest(segmentation);
  if (segmentation.label && segmentation.kind == InputKind::Grayscale)
    throw ArgumentError("--label picks a label of a label map, and --inputKind Grayscale thresholds the volume "
                        "instead: give one of them");
  if (request.empty())
    return;
  if (segmentation.kind == InputKind::LabelMap)
  {
    std::cerr << "SliceMesh: warning: " << request
              << " is for a grayscale volume; --inputKind LabelMap meshes the labels, so it has no effect" << std::endl;
    return;
  }
  if (segmentation.kind == InputKind::Automatic && segmentation.label)
    throw ArgumentError("--label picks a label of a label map, and " + request +
                        " is an option for a grayscale volume: give one of them (--inputKind says which the volume is)");
  if (segmentation.kind == InputKind::Automatic && settings.multiLabel.enabled)
    throw ArgumentError("one mesh per label (--splitLabels, --labels, --outputDirectory) needs a label map, and " +
                        request + " is an option for a grayscale volume: give one of them");
}

void readArguments(const ParsedArguments& arguments, PipelineSettings& settings)
{
  const ProcessingDimension dimension =
    arguments.text("processing") == "Volume" ? ProcessingDimension::Volume3D : ProcessingDimension::Slice2D;

  GrayscaleSegmentationOptions& grayscale = settings.segmentation.grayscale;
  grayscale.dimension = dimension;
  grayscale.denoising.gaussianSigma = arguments.number("gaussianSigma");
  grayscale.denoising.diffusionIterations = static_cast<unsigned int>(arguments.integer("diffusionIterations"));
  grayscale.denoising.diffusionConductance = arguments.number("diffusionConductance");
  const std::string& method = arguments.text("thresholdMethod");
  grayscale.method = method == "Window" ? ThresholdMethod::Window
                     : method == "Manual" ? ThresholdMethod::Manual
                                          : ThresholdMethod::Otsu;
  grayscale.threshold = arguments.number("threshold");
  grayscale.lower = arguments.number("lowerThreshold");
  grayscale.upper = arguments.number("upperThreshold");
  if (grayscale.method == ThresholdMethod::Window && grayscale.lower > grayscale.upper)
    throw ArgumentError("--lowerThreshold is above --upperThreshold");
  grayscale.otsuThresholds = static_cast<unsigned int>(arguments.integer("otsuThresholds"));
  grayscale.otsuClass = static_cast<unsigned int>(arguments.integer("otsuClass"));
  if (grayscale.otsuClass > grayscale.otsuThresholds + 1)
    throw ArgumentError("--otsuClass " + std::to_string(grayscale.otsuClass) + " does not exist with " +
                        std::to_string(grayscale.otsuThresholds) + " Otsu threshold(s)");
  grayscale.regions = arguments.text("regionMode") == "Edges" ? RegionMode::Edges : RegionMode::Intensity;
  grayscale.canny.variance = arguments.number("cannyVariance");
  grayscale.canny.lowerThreshold = arguments.number("cannyLowerThreshold");
  grayscale.canny.upperThreshold = arguments.number("cannyUpperThreshold");
  if (grayscale.regions == RegionMode::Edges && grayscale.canny.lowerThreshold > grayscale.canny.upperThreshold)
    throw ArgumentError("--cannyLowerThreshold is above --cannyUpperThreshold");

  MaskRefinementOptions& refinement = settings.segmentation.refinement;
  refinement.dimension = dimension;
  refinement.fillHoles = arguments.flag("fillHoles");
  refinement.minimumArea = arguments.number("minimumArea");
  for (const std::string& point : split(arguments.text("seed"), ';'))
  {
    const std::vector<std::string> coordinates = split(point, ',');
    if (coordinates.size() != 3)
      throw ArgumentError("--seed: '" + point + "' needs 3 comma-separated numbers (LPS mm)");
    refinement.seeds.push_back(
      { toNumber(coordinates[0], "--seed"), toNumber(coordinates[1], "--seed"), toNumber(coordinates[2], "--seed") });
  }

  MultiLabelSettings& multi = settings.multiLabel;
  for (const std::string& label : labelItems(arguments.text("labels")))
  {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(label.c_str(), &end, 10);
    if (end != label.c_str() && *end == '\0')
    {
      // Voxels of value 0 are the background the labels are cut from, never a structure.
      if (value == 0)
        throw ArgumentError("--labels: 0 is the background, not a label (give the labels to mesh, e.g. --labels 1,3)");
      // A label is an int: a value beyond one would wrap to another label (4294967297 to 1).
      if (errno == ERANGE || value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
        throw ArgumentError("--labels: " + label + " is outside the range " +
                            std::to_string(std::numeric_limits<int>::min()) + " .. " +
                            std::to_string(std::numeric_limits<int>::max()));
      multi.labels.push_back(static_cast<int>(value));
    }
    else
      multi.labelNames.push_back(label);
  }
  // --label picks one label for one mesh, --labels several for one mesh each: given both, one of
  // them would be ignored without a word.
  if (settings.segmentation.label && (!multi.labels.empty() || !multi.labelNames.empty()))
    throw ArgumentError("--label and --labels both pick labels: give one of them (--labels " +
                        std::to_string(*settings.segmentation.label) + " for that label alone, in its own file)");
  multi.outputDirectory = arguments.text("outputDirectory");
  multi.colorTable = arguments.text("colorTable");
  multi.enabled = arguments.flag("splitLabels") || !multi.labels.empty() || !multi.labelNames.empty() ||
                  !multi.outputDirectory.empty();
  // Nor --label beside --splitLabels or --outputDirectory, which mesh every label.
  if (settings.segmentation.label && multi.enabled)
    throw ArgumentError(std::string("--label picks one label for one mesh and ") +
                        (arguments.flag("splitLabels") ? "--splitLabels" : "--outputDirectory") +
                        " meshes every label, each in its own file: give one of them (--labels " +
                        std::to_string(*settings.segmentation.label) + " for that label alone, in its own file)");
  checkInputKindOptions(settings);
}


} // namespace

void readSegmentationArguments(const ParsedArguments& arguments, PipelineSettings& settings)
{
  try
  {
    readArguments(arguments, settings);
  }
  catch (const ArgumentError& e)
  {
    throw PipelineFailure(BadArguments, e.what());
  }
}

} // namespace slicemesh::cli

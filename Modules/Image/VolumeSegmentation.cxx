// From a label map or a grayscale volume to a binary mask: label selection, or a threshold
// (given, or Otsu's).
#include "VolumeSegmentation.h"

#include "GrayscaleSegmentation.h"

#include "Core/SliceMeshTypes.h"

#include "itkOtsuThresholdCalculator.h"
#include "itkScalarImageToHistogramGenerator.h"

#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace slicemesh
{
namespace
{

/** The distinct voxel values of a label map, or nothing when the volume is not one: a voxel that
 *  is negative, fractional or non-finite, or more than 65535 distinct values. One pass over the
 *  voxels; the common small labels are tallied in a table, rare large ones in a set. */
std::optional<std::vector<double>> labelsOf(const ScalarVolume* volume)
{
  constexpr std::size_t maxLabels = 65535;
  constexpr std::size_t tableSize = 65536;
  std::vector<unsigned char> seenSmall(tableSize, 0);
  std::set<float> seenLarge;
  std::size_t distinct = 0;

  const float* voxel = volume->GetBufferPointer();
  const float* end = voxel + volume->GetBufferedRegion().GetNumberOfPixels();
  for (; voxel != end; ++voxel)
  {
    const float value = *voxel;
    // NaN fails the first test, fractions the second (std::floor keeps infinities, so test them).
    if (!(value >= 0.0f) || std::floor(value) != value || std::isinf(value))
      return std::nullopt;
    if (value < static_cast<float>(tableSize))
    {
      unsigned char& seen = seenSmall[static_cast<std::size_t>(value)];
      if (seen)
        continue;
      seen = 1;
    }
    else if (!seenLarge.insert(value).second)
      continue;
    if (++distinct > maxLabels)
      return std::nullopt;
  }

  std::vector<double> labels;
  for (std::size_t value = 0; value < tableSize; ++value)
    if (seenSmall[value])
      labels.push_back(static_cast<double>(value));
  for (float value : seenLarge)
    labels.push_back(value);
  return labels;
}

/** Otsu's threshold on a 256-bin histogram of the voxel values (ITK's calculator). */
double otsuThreshold(const ScalarVolume* volume)
{
  using HistogramGenerator = itk::Statistics::ScalarImageToHistogramGenerator<ScalarVolume>;
  auto histogramGenerator = HistogramGenerator::New();
  histogramGenerator->SetInput(volume);
  histogramGenerator->SetNumberOfBins(256);
  histogramGenerator->Compute();

  using Calculator = itk::OtsuThresholdCalculator<HistogramGenerator::HistogramType, double>;
  auto calculator = Calculator::New();
  calculator->SetInput(histogramGenerator->GetOutput());
  calculator->Compute();
  return calculator->GetThreshold();
}

MaskVolume::Pointer allocateMaskLike(const ScalarVolume* volume)
{
  auto mask = MaskVolume::New();
  mask->CopyInformation(volume);
  mask->SetRegions(volume->GetBufferedRegion());
  mask->Allocate();
  return mask;
}

/** Fills the mask with 1 where inside(voxel) holds; returns the count of inside voxels. */
template <typename InsideTest>
std::size_t fillMask(const ScalarVolume* volume, MaskVolume* mask, InsideTest inside)
{
  const float* voxel = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  unsigned char* out = mask->GetBufferPointer();
  std::size_t insideCount = 0;
  for (std::size_t n = 0; n < count; ++n)
  {
    const bool in = inside(voxel[n]);
    out[n] = in ? 1 : 0;
    insideCount += in;
  }
  return insideCount;
}

std::string listOfLabels(const std::vector<double>& labels)
{
  constexpr std::size_t shown = 20;
  std::ostringstream list;
  std::size_t listed = 0;
  for (double label : labels)
  {
    if (label == 0.0)
      continue; // the background is not a structure
    if (listed == shown)
    {
      list << ", ...";
      break;
    }
    list << (listed ? ", " : "") << label;
    ++listed;
  }
  return listed ? list.str() : std::string("none besides background 0");
}

std::string volumeName(const ScalarVolume* volume)
{
  const auto size = volume->GetBufferedRegion().GetSize();
  std::ostringstream name;
  name << "volume " << size[0] << "x" << size[1] << "x" << size[2];
  return name.str();
}

} // namespace

MaskVolume::Pointer segmentVolume(const ScalarVolume* volume, const SegmentationOptions& options)
{
  if (!volume || volume->GetBufferedRegion().GetNumberOfPixels() == 0)
    throw Error("segmentVolume: an empty volume");

  std::optional<std::vector<double>> labels;
  InputKind kind = options.kind;
  if (kind != InputKind::Grayscale)
  {
    labels = labelsOf(volume);
    if (kind == InputKind::Automatic)
      kind = labels ? InputKind::LabelMap : InputKind::Grayscale;
  }

  MaskVolume::Pointer mask = allocateMaskLike(volume);
  if (kind == InputKind::LabelMap)
  {
    if (options.label)
    {
      const float wanted = static_cast<float>(*options.label);
      if (fillMask(volume, mask, [wanted](float v) { return v == wanted; }) == 0)
      {
        std::ostringstream message;
        message << volumeName(volume) << ": no voxel has label " << *options.label << "; labels present: "
                << (labels ? listOfLabels(*labels) : std::string("none (not a label map)"));
        throw Error(message.str());
      }
    }
    else if (fillMask(volume, mask, [](float v) { return v != 0.0f && !std::isnan(v); }) == 0)
      throw Error(volumeName(volume) + ": every voxel is 0; nothing to mesh");
    refineMask(mask, options.refinement);
    return mask;
  }

  if (options.grayscale.beyondPlainThreshold())
  {
    GrayscaleSegmentationOptions grayscale = options.grayscale;
    if (options.threshold && grayscale.method == ThresholdMethod::Otsu)
    {
      grayscale.method = ThresholdMethod::Manual;
      grayscale.threshold = *options.threshold;
    }
    try
    {
      GrayscaleMask segmented = segmentGrayscale(volume, grayscale);
      refineMask(segmented.mask, options.refinement, segmented.edgeVoxels);
      return segmented.mask;
    }
    catch (const Error& e)
    {
      throw Error(volumeName(volume) + ": " + e.what());
    }
  }

  double threshold = 0.0;
  if (options.threshold)
    threshold = *options.threshold;
  else
  {
    // Otsu's method needs two populations; a uniform volume has none to separate.
    const float* voxel = volume->GetBufferPointer();
    const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
    bool uniform = true;
    for (std::size_t n = 1; n < count && uniform; ++n)
      uniform = voxel[n] == voxel[0];
    if (uniform)
      throw Error(volumeName(volume) + ": every voxel has the same value; Otsu's threshold separates nothing");
    threshold = otsuThreshold(volume);
  }
  const auto inside = [threshold](float v) { return static_cast<double>(v) >= threshold; };
  if (fillMask(volume, mask, inside) == 0)
  {
    std::ostringstream message;
    message << volumeName(volume) << ": no voxel is at or above the threshold " << threshold << " ("
            << intensityRangeText(volume) << ")";
    throw Error(message.str());
  }
  refineMask(mask, options.refinement);
  return mask;
}

} // namespace slicemesh

// From a label map or a grayscale volume to a binary mask: label selection, or a threshold
// (given, or Otsu's).
#include "VolumeSegmentation.h"

#include "FiniteHistogram.h"
#include "GrayscaleSegmentation.h"
#include "StoredVolume.h"

#include "Core/ParallelFor.h"
#include "Core/SliceMeshTypes.h"

#include "itkOtsuThresholdCalculator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>
#include <vector>

namespace slicemesh
{
namespace
{

/** Up to this many distinct values a volume of whole non-negative values is a label map whatever
 *  its voxels' arrangement (a mask, a few structures, a row of specks). */
constexpr std::size_t fewLabels = 16;
/** With more, a label map keeps neighbouring voxels of its foreground equal in at least this share
 *  of the pairs. Measured over the three axes, pairs of two non-zero voxels: the atlases of 33 to
 *  725 labels at 1 and 2 mm 0.82 to 0.98 (touching labels differ only along their borders), T1 MRIs
 *  of 81 to 274 whole values (skull-stripped or not) 0.09 to 0.24; a map of separate small lesions,
 *  however small, 1. */
constexpr double leastEqualNeighbours = 0.5;

/** The share of pairs of face neighbours, along the three axes, holding equal values, among the
 *  pairs of two non-zero voxels (1 when there is none). Slices side by side on every thread; the
 *  counts are whole numbers, the same in any order. */
template <typename TImage>
double equalNeighbourFraction(const TImage* volume)
{
  const auto size = volume->GetBufferedRegion().GetSize();
  const std::size_t nx = size[0], ny = size[1], nz = size[2];
  const auto* voxels = volume->GetBufferPointer();
  struct Pairs
  {
    std::size_t equal = 0, pairs = 0;
  };
  const std::size_t slicesPerRange = std::max<std::size_t>(1, (std::size_t(1) << 20) / std::max<std::size_t>(1, nx * ny));
  const std::vector<Pairs> ranges = fixedRangeResults<Pairs>(
    nz, slicesPerRange, 0,
    [&](Pairs& counted, std::size_t firstSlice, std::size_t lastSlice)
    {
      const auto count = [&](std::size_t a, std::size_t b)
      {
        if (voxels[a] == 0 || voxels[b] == 0)
          return;
        ++counted.pairs;
        counted.equal += voxels[a] == voxels[b];
      };
      for (std::size_t k = firstSlice; k < lastSlice; ++k)
        for (std::size_t j = 0; j < ny; ++j)
          for (std::size_t i = 0; i < nx; ++i)
          {
            const std::size_t at = (k * ny + j) * nx + i;
            if (i + 1 < nx)
              count(at, at + 1);
            if (j + 1 < ny)
              count(at, at + nx);
            if (k + 1 < nz)
              count(at, at + nx * ny);
          }
    });
  std::size_t equal = 0, pairs = 0;
  for (const Pairs& range : ranges)
  {
    equal += range.equal;
    pairs += range.pairs;
  }
  return pairs == 0 ? 1.0 : static_cast<double>(equal) / static_cast<double>(pairs);
}

/** Why a voxel's value cannot be a label (null: it can): not finite, negative, or not whole. */
template <typename Pixel>
const char* whyNotALabel(Pixel value)
{
  // NaN and infinities fail the first test (std::floor keeps infinities), fractions the third.
  if constexpr (std::is_floating_point_v<Pixel>)
  {
    if (std::isnan(value) || std::isinf(value))
      return "a voxel is not finite";
    if (value < 0.0f)
      return "a voxel is negative";
    if (std::floor(value) != value)
      return "a voxel is not a whole number";
  }
  else if constexpr (std::is_signed_v<Pixel>)
  {
    if (value < 0)
      return "a voxel is negative";
  }
  return nullptr;
}

constexpr std::size_t maxLabels = 65535;
constexpr std::size_t tableSize = 65536;

/** The most values of tableSize and over a range's set holds: each range holds its own set until
 *  they are merged, and a volume of many such values is gone through in order instead. */
constexpr std::size_t mostLargeValuesInARange = 4096;

/** The distinct values of voxels [first, last), the small ones flagged in a table, the others in a
 *  set; false (stopped early) at a value that cannot be a label or past mostLargeValuesInARange
 *  large ones. */
template <typename Pixel>
bool tallyValues(const Pixel* first, const Pixel* last, std::vector<unsigned char>& seenSmall, std::set<Pixel>& seenLarge)
{
  seenSmall.assign(tableSize, 0);
  for (const Pixel* voxel = first; voxel != last; ++voxel)
  {
    const Pixel value = *voxel;
    if (whyNotALabel(value))
      return false;
    if (static_cast<double>(value) < static_cast<double>(tableSize))
      seenSmall[static_cast<std::size_t>(value)] = 1;
    else if (seenLarge.insert(value).second && seenLarge.size() > mostLargeValuesInARange)
      return false;
  }
  return true;
}

/** The values flagged in the table, then those in the set, in increasing order each. */
template <typename Pixel>
std::vector<double> valuesOf(const std::vector<unsigned char>& seenSmall, const std::set<Pixel>& seenLarge)
{
  std::vector<double> values;
  for (std::size_t value = 0; value < tableSize; ++value)
    if (seenSmall[value])
      values.push_back(static_cast<double>(value));
  for (Pixel value : seenLarge)
    values.push_back(static_cast<double>(value));
  return values;
}

/** The distinct voxel values, in one pass in memory order from voxel `from` on, those of the
 *  voxels before it given (`seenSmall`, empty for none, and `seenLarge`), or nothing (then `whyNot`,
 *  when given, says why: the first voxel that cannot be a label, or the value that made more than
 *  maxLabels). The exact account of a volume that is no label map; distinctValues is the fast way
 *  there. */
template <typename TImage>
std::optional<std::vector<double>> distinctValuesInOrder(const TImage* volume, std::string* whyNot,
                                                         std::size_t from = 0,
                                                         std::vector<unsigned char> seenSmall = {},
                                                         std::set<typename TImage::PixelType> seenLarge = {})
{
  auto notLabels = [whyNot](const std::string& reason, double value)
  {
    if (whyNot)
    {
      std::ostringstream text;
      text << reason << " (" << value << ")";
      *whyNot = text.str();
    }
    return std::nullopt;
  };
  using Pixel = typename TImage::PixelType;
  if (seenSmall.empty())
    seenSmall.assign(tableSize, 0);
  std::size_t distinct = static_cast<std::size_t>(std::count(seenSmall.begin(), seenSmall.end(), 1)) + seenLarge.size();

  const Pixel* voxel = volume->GetBufferPointer() + from;
  const Pixel* end = volume->GetBufferPointer() + volume->GetBufferedRegion().GetNumberOfPixels();
  for (; voxel != end; ++voxel)
  {
    const Pixel value = *voxel;
    if (const char* reason = whyNotALabel(value))
      return notLabels(reason, static_cast<double>(value));
    if (static_cast<double>(value) < static_cast<double>(tableSize))
    {
      unsigned char& seen = seenSmall[static_cast<std::size_t>(value)];
      if (seen)
        continue;
      seen = 1;
    }
    else if (!seenLarge.insert(value).second)
      continue;
    if (++distinct > maxLabels)
      return notLabels("more than 65535 distinct values, the last", static_cast<double>(value));
  }
  return valuesOf(seenSmall, seenLarge);
}

/** distinctValuesInOrder, the volume's ranges tallied side by side on every thread and merged in
 *  order (the same values). From the first range that stopped early, or that would take the count
 *  past maxLabels, the volume is gone through in order, with the values of the ranges before it:
 *  the exact account of why it is no label map, without going over those ranges again. */
template <typename TImage>
std::optional<std::vector<double>> distinctValues(const TImage* volume, std::string* whyNot)
{
  using Pixel = typename TImage::PixelType;
  struct Tally
  {
    std::vector<unsigned char> seenSmall;
    std::set<Pixel> seenLarge;
    bool complete = false;
  };
  const Pixel* voxels = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  constexpr std::size_t voxelsPerRange = std::size_t(1) << 22;
  std::vector<Tally> tallies = fixedRangeResults<Tally>(
    count, voxelsPerRange, 0, [&](Tally& tally, std::size_t first, std::size_t last)
    { tally.complete = tallyValues(voxels + first, voxels + last, tally.seenSmall, tally.seenLarge); });
  std::vector<unsigned char> seenSmall(tableSize, 0);
  std::set<Pixel> seenLarge;
  std::size_t distinct = 0;
  for (std::size_t r = 0; r < tallies.size(); ++r)
  {
    Tally& tally = tallies[r];
    std::size_t added = 0;
    if (tally.complete)
    {
      for (std::size_t value = 0; value < tableSize; ++value)
        added += tally.seenSmall[value] && !seenSmall[value];
      for (Pixel value : tally.seenLarge)
        added += seenLarge.count(value) == 0;
    }
    if (!tally.complete || distinct + added > maxLabels)
      return distinctValuesInOrder(volume, whyNot, r * voxelsPerRange, std::move(seenSmall), std::move(seenLarge));
    for (std::size_t value = 0; value < tableSize; ++value)
      seenSmall[value] |= tally.seenSmall[value];
    seenLarge.merge(tally.seenLarge);
    distinct += added;
    tally = Tally();
  }
  return valuesOf(seenSmall, seenLarge);
}

/** The distinct voxel values of a label map, or nothing when the volume is not one: a voxel that
 *  is negative, fractional or non-finite, more than 65535 distinct values, or more than a few
 *  values that change from voxel to voxel as intensities do (then `whyNot`, when given, says
 *  which). One pass over the voxels, a second for many values, each on every thread (but for the
 *  account of a volume that is no label map, from its first range that stops early). */
template <typename TImage>
std::optional<std::vector<double>> labelsOf(const TImage* volume, std::string* whyNot = nullptr)
{
  std::optional<std::vector<double>> labels = distinctValues(volume, whyNot);
  if (!labels)
    return std::nullopt;
  const std::size_t distinct = labels->size();

  // Whole non-negative values alone do not make a label map: an MR of 8 or 16 bits has them too.
  // A label map is piecewise constant; an image's intensities change from voxel to voxel.
  if (distinct > fewLabels)
  {
    const double equal = equalNeighbourFraction(volume);
    if (equal < leastEqualNeighbours)
    {
      if (whyNot)
      {
        std::ostringstream text;
        text << distinct << " whole values, and neighbouring non-zero voxels differ in "
             << std::lround(100.0 * (1.0 - equal)) << "% of the pairs, as an image's intensities do";
        *whyNot = text.str();
      }
      return std::nullopt;
    }
  }

  return labels;
}

/** Otsu's threshold on a 256-bin histogram of the finite voxel values (ITK's calculator). */
double otsuThreshold(const ScalarVolume* volume)
{
  using Calculator = itk::OtsuThresholdCalculator<IntensityHistogram, double>;
  auto calculator = Calculator::New();
  calculator->SetInput(finiteIntensityHistogram(volume, 256));
  calculator->Compute();
  return calculator->GetThreshold();
}

MaskVolume::Pointer allocateMaskLike(const itk::ImageBase<3>* volume)
{
  auto mask = MaskVolume::New();
  mask->CopyInformation(volume);
  mask->SetRegions(volume->GetBufferedRegion());
  mask->Allocate();
  return mask;
}

/** Fills the mask with 1 where inside(voxel) holds; returns the count of inside voxels. In ranges
 *  on every thread: on one, this pass over a large volume (and the first touch of the mask's pages)
 *  kept the other cores waiting at the start of a run. */
template <typename TImage, typename InsideTest>
std::size_t fillMask(const TImage* volume, MaskVolume* mask, InsideTest inside)
{
  const auto* voxel = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  unsigned char* out = mask->GetBufferPointer();
  constexpr std::size_t voxelsPerRange = std::size_t(1) << 20;
  const std::vector<std::size_t> insideCounts =
    fixedRangeResults<std::size_t>(count, voxelsPerRange, 0,
                                   [&](std::size_t& insideCount, std::size_t first, std::size_t last)
                                   {
                                     for (std::size_t n = first; n < last; ++n)
                                     {
                                       const bool in = inside(voxel[n]);
                                       out[n] = in ? 1 : 0;
                                       insideCount += in;
                                     }
                                   });
  return std::accumulate(insideCounts.begin(), insideCounts.end(), std::size_t(0));
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

std::string volumeName(const itk::ImageBase<3>* volume)
{
  const auto size = volume->GetBufferedRegion().GetSize();
  std::ostringstream name;
  name << "volume " << size[0] << "x" << size[1] << "x" << size[2];
  return name.str();
}

/** Why a label map's mask of every non-zero voxel is empty: "every voxel is 0", or, where some are
 *  NaN (taken as background, as ITK's threshold filters leave them out), that and how many are NaN
 *  and the first of them: a float volume masked with NaN outside its structures is common, and one
 *  all 0 and NaN should not read as all 0. */
template <typename TImage>
std::string nothingNonZeroText(const TImage* volume)
{
  using Pixel = typename TImage::PixelType;
  std::ostringstream text;
  text << volumeName(volume) << ": every voxel is 0";
  if constexpr (std::is_floating_point_v<Pixel>)
  {
    const Pixel* voxels = volume->GetBufferPointer();
    const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
    const auto isNaN = [](Pixel v) { return std::isnan(v); };
    const Pixel* first = std::find_if(voxels, voxels + count, isNaN);
    if (first != voxels + count)
    {
      const auto size = volume->GetBufferedRegion().GetSize();
      const auto start = volume->GetBufferedRegion().GetIndex();
      const std::size_t at = static_cast<std::size_t>(first - voxels);
      const auto nans = std::count_if(first, voxels + count, isNaN);
      text << " or NaN, taken as background (" << nans << (nans == 1 ? " voxel is" : " voxels are")
           << " NaN, the first at index (" << start[0] + static_cast<long>(at % size[0]) << ", "
           << start[1] + static_cast<long>(at / size[0] % size[1]) << ", "
           << start[2] + static_cast<long>(at / (size[0] * size[1])) << "))";
    }
  }
  text << "; nothing to mesh";
  return text.str();
}

/** The label map's mask: the voxels of the label asked for, or every non-zero one; refined.
 *  `labels`: the label map's labels (for the message when the label is absent), if it is one. */
template <typename TImage>
MaskVolume::Pointer labelMapMask(const TImage* volume, const SegmentationOptions& options,
                                 const std::optional<std::vector<double>>& labels)
{
  using Pixel = typename TImage::PixelType;
  MaskVolume::Pointer mask = allocateMaskLike(volume);
  if (options.label)
  {
    // Integers compared exactly (float would take 16777217 for 16777216); a float map as float.
    const int wanted = *options.label;
    const auto isWanted = [wanted](Pixel v)
    {
      if constexpr (std::is_integral_v<Pixel>)
        return static_cast<std::int64_t>(v) == wanted;
      else
        return v == static_cast<float>(wanted);
    };
    if (fillMask(volume, mask, isWanted) == 0)
    {
      std::ostringstream message;
      message << volumeName(volume) << ": no voxel has label " << *options.label << "; labels present: "
              << (labels ? listOfLabels(*labels) : std::string("none (not a label map)"));
      throw Error(message.str());
    }
  }
  else if (fillMask(volume, mask, [](Pixel v) { return v != Pixel(0) && !std::isnan(static_cast<float>(v)); }) == 0)
    throw Error(nothingNonZeroText(volume));
  refineMask(mask, options.refinement);
  return mask;
}

/** The line that says which kind an Automatic run chose, and why. */
std::string automaticChoiceText(const std::optional<std::vector<double>>& labels, const std::string& whyNot,
                                const std::string& request)
{
  std::ostringstream text;
  if (!request.empty())
    text << "input kind Grayscale, chosen from the options: " << request
         << " is an option for a grayscale volume (--inputKind LabelMap meshes its labels instead)";
  else if (labels)
    text << "input kind LabelMap, chosen from the voxels: " << labels->size() << " whole non-negative values, "
         << labels->front() << " to " << labels->back() << " (--inputKind Grayscale thresholds it instead)";
  else
    text << "input kind Grayscale, chosen from the voxels: " << whyNot
         << " (--inputKind LabelMap meshes its non-zero voxels instead)";
  return text.str();
}

} // namespace

std::string grayscaleRequest(const SegmentationOptions& options)
{
  const GrayscaleSegmentationOptions& g = options.grayscale;
  if (options.threshold || g.method == ThresholdMethod::Manual)
    return "--thresholdMethod Manual";
  if (g.method == ThresholdMethod::Window)
    return "--thresholdMethod Window";
  if (g.otsuThresholds != 1)
    return "--otsuThresholds " + std::to_string(g.otsuThresholds);
  if (g.otsuClass != 0 && g.otsuClass != 2)
    return "--otsuClass " + std::to_string(g.otsuClass);
  if (g.regions == RegionMode::Edges)
    return "--regionMode Edges";
  if (g.denoising.gaussianSigma > 0.0)
    return "--gaussianSigma";
  if (g.denoising.diffusionIterations > 0)
    return "--diffusionIterations";
  return {};
}

MaskVolume::Pointer segmentVolume(const ScalarVolume* volume, const SegmentationOptions& options,
                                  std::string* automaticChoice)
{
  if (!volume || volume->GetBufferedRegion().GetNumberOfPixels() == 0)
    throw Error("segmentVolume: an empty volume");

  std::optional<std::vector<double>> labels;
  InputKind kind = options.kind;
  const std::string request = options.kind == InputKind::Automatic ? grayscaleRequest(options) : std::string();
  if (!request.empty())
  {
    kind = InputKind::Grayscale;
    if (automaticChoice)
      *automaticChoice = automaticChoiceText(labels, {}, request);
  }
  if (kind != InputKind::Grayscale)
  {
    std::string whyNot;
    labels = labelsOf(volume, &whyNot);
    if (kind == InputKind::Automatic)
    {
      kind = labels ? InputKind::LabelMap : InputKind::Grayscale;
      if (automaticChoice)
        *automaticChoice = automaticChoiceText(labels, whyNot, {});
      if (!labels && options.label)
        throw Error(volumeName(volume) + ": --label " + std::to_string(*options.label) +
                    " picks a label of a label map, but this volume was taken as grayscale (" + whyNot +
                    "); give --inputKind LabelMap to mesh its voxels of value " + std::to_string(*options.label));
    }
  }

  if (kind == InputKind::LabelMap)
    return labelMapMask(volume, options, labels);

  MaskVolume::Pointer mask = allocateMaskLike(volume);
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
    // Otsu's method needs two populations; a uniform volume has none to separate (NaN and
    // infinities are not intensities: left out, as from the histogram).
    const auto range = finiteIntensityRange(volume);
    if (!range)
      throw Error(volumeName(volume) + ": no voxel has a finite intensity (every one is NaN or infinite); nothing to threshold");
    if (range->first == range->second)
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

MaskVolume::Pointer segmentStoredVolume(StoredVolume volume, const SegmentationOptions& options,
                                        std::string* automaticChoice)
{
  if (auto* asFloat = std::get_if<ScalarVolume::Pointer>(&volume))
    return segmentVolume(*asFloat, options, automaticChoice);
  const itk::ImageBase<3>* image = imageOf(volume);
  if (!image || image->GetBufferedRegion().GetNumberOfPixels() == 0)
    throw Error("segmentVolume: an empty volume");
  // Integers: a label map unless grayscale is asked for or a voxel is negative (labelsOf).
  std::string whyNot;
  const std::string request = options.kind == InputKind::Automatic ? grayscaleRequest(options) : std::string();
  const std::optional<std::vector<double>> labels =
    options.kind == InputKind::Grayscale || !request.empty()
      ? std::nullopt
      : std::visit([&](const auto& stored) { return labelsOf(stored.GetPointer(), &whyNot); }, volume);
  if (options.kind == InputKind::Automatic && automaticChoice)
    *automaticChoice = automaticChoiceText(labels, whyNot, request);
  if (options.kind == InputKind::LabelMap || (options.kind == InputKind::Automatic && labels))
    return std::visit([&](const auto& stored) { return labelMapMask(stored.GetPointer(), options, labels); }, volume);
  if (options.kind == InputKind::Automatic && request.empty() && options.label)
    throw Error(volumeName(image) + ": --label " + std::to_string(*options.label) +
                " picks a label of a label map, but this volume was taken as grayscale (" + whyNot +
                "); give --inputKind LabelMap to mesh its voxels of value " + std::to_string(*options.label));
  // Grayscale methods work on float: the stored voxels go as soon as they are widened. The choice
  // is made: the widened volume is segmented as grayscale.
  const ScalarVolume::Pointer widened = floatVolumeOf(volume);
  volume = ScalarVolume::Pointer();
  SegmentationOptions grayscale = options;
  grayscale.kind = InputKind::Grayscale;
  return segmentVolume(widened, grayscale);
}

} // namespace slicemesh

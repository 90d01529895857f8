// Denoise -> intensity criterion -> (edge mode) cut along Canny edges.
#include "GrayscaleSegmentation.h"

#include "FiniteHistogram.h"
#include "OtsuThresholds.h"
#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace slicemesh
{

std::string intensityRangeText(const ScalarVolume* volume)
{
  const auto range = finiteIntensityRange(volume);
  std::ostringstream text;
  if (!range)
    text << "no voxel has a finite intensity";
  else
    text << "the intensities run from " << static_cast<double>(range->first) << " to "
         << static_cast<double>(range->second);
  return text.str();
}

namespace
{

/** The volume the denoising reads: `volume` itself, or, where some voxels have no intensity (NaN or
 *  infinite: outside a processed MRI's brain mask, say) and a filter will spread them, a copy with
 *  those voxels at the lowest finite intensity, as background. Spread by a Gaussian, a few NaN
 *  voxels made every voxel NaN and nothing could be thresholded. */
ScalarVolume::ConstPointer finiteForSmoothing(const ScalarVolume* volume, const DenoisingOptions& denoising)
{
  if (!denoising.any())
    return volume;
  const float* voxel = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  const auto range = finiteIntensityRange(volume);
  if (!range || std::all_of(voxel, voxel + count, [](float v) { return std::isfinite(v); }))
    return volume; // no finite voxel, which the thresholds report; or every voxel finite
  const float lowest = range->first;
  ScalarVolume::Pointer copy = ScalarVolume::New();
  copy->CopyInformation(volume);
  copy->SetRegions(volume->GetBufferedRegion());
  copy->Allocate();
  float* out = copy->GetBufferPointer();
  for (std::size_t n = 0; n < count; ++n)
    out[n] = std::isfinite(voxel[n]) ? voxel[n] : lowest;
  return copy;
}

} // namespace

GrayscaleMask segmentGrayscale(const ScalarVolume* volume, const GrayscaleSegmentationOptions& options)
{
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool upperInclusive = true;
  switch (options.method)
  {
    case ThresholdMethod::Manual:
      lower = options.threshold;
      break;
    case ThresholdMethod::Window:
      if (!(options.lower <= options.upper))
      {
        std::ostringstream message;
        message << "intensity window: the lower bound " << options.lower << " is above the upper bound "
                << options.upper;
        throw Error(message.str());
      }
      lower = options.lower;
      upper = options.upper;
      break;
    case ThresholdMethod::Otsu:
    {
      const unsigned int classes = options.otsuThresholds + 1;
      const unsigned int wanted = options.otsuClass == 0 ? classes : options.otsuClass;
      if (wanted > classes)
      {
        std::ostringstream message;
        message << "Otsu class " << options.otsuClass << " does not exist: " << options.otsuThresholds
                << " threshold(s) make " << classes << " classes (1 = darkest)";
        throw Error(message.str());
      }
      const std::vector<double> thresholds = otsuThresholds(volume, options.otsuThresholds);
      // Class c holds t[c-2] <= v < t[c-1] (t[-1] = -inf, t[n] = +inf).
      if (wanted >= 2)
        lower = thresholds[wanted - 2];
      if (wanted <= options.otsuThresholds)
      {
        upper = thresholds[wanted - 1];
        upperInclusive = false;
      }
      break;
    }
  }

  DenoisingOptions denoising = options.denoising;
  denoising.dimension = options.dimension;
  const ScalarVolume::ConstPointer smoothable = finiteForSmoothing(volume, denoising);
  const ScalarVolume::Pointer smooth = denoiseVolume(smoothable, denoising);

  GrayscaleMask result;
  result.mask = MaskVolume::New();
  result.mask->CopyInformation(volume);
  result.mask->SetRegions(volume->GetBufferedRegion());
  result.mask->Allocate();
  const float* in = smooth->GetBufferPointer();
  unsigned char* out = result.mask->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  std::size_t inside = 0;
  const float* given = volume->GetBufferPointer();
  for (std::size_t n = 0; n < count; ++n)
  {
    const double v = in[n];
    // A voxel without an intensity (NaN, infinite) is outside, smoothed or not.
    const bool in = std::isfinite(given[n]) && v >= lower && (upperInclusive ? v <= upper : v < upper);
    out[n] = in ? 1 : 0;
    inside += in;
  }
  if (inside == 0)
  {
    std::ostringstream message;
    message << "no voxel lies in the intensity range [" << lower << ", " << upper << (upperInclusive ? "]" : ")")
            << " (" << intensityRangeText(smooth) << (smooth.GetPointer() == volume ? "" : " after smoothing") << ")";
    throw Error(message.str());
  }

  if (options.regions == RegionMode::Edges)
  {
    const MaskVolume::Pointer edges = cannyEdges(smooth, options.canny, options.dimension);
    result.edgeVoxels = MaskVolume::New();
    result.edgeVoxels->CopyInformation(volume);
    result.edgeVoxels->SetRegions(volume->GetBufferedRegion());
    result.edgeVoxels->Allocate();
    const unsigned char* edge = edges->GetBufferPointer();
    unsigned char* cut = result.edgeVoxels->GetBufferPointer();
    for (std::size_t n = 0; n < count; ++n)
    {
      cut[n] = out[n] && edge[n] ? 1 : 0;
      if (cut[n])
        out[n] = 0;
    }
  }
  return result;
}

} // namespace slicemesh

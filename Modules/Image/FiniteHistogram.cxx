#include "FiniteHistogram.h"

#include "Core/SliceMeshTypes.h"

#include <cmath>

namespace slicemesh
{

std::optional<std::pair<float, float>> finiteIntensityRange(const ScalarVolume* volume)
{
  const float* voxel = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  std::optional<std::pair<float, float>> range;
  for (std::size_t n = 0; n < count; ++n)
    if (std::isfinite(voxel[n]))
    {
      if (!range)
        range = { voxel[n], voxel[n] };
      range->first = std::min(range->first, voxel[n]);
      range->second = std::max(range->second, voxel[n]);
    }
  return range;
}

IntensityHistogram::Pointer finiteIntensityHistogram(const ScalarVolume* volume, unsigned int bins)
{
  const auto range = finiteIntensityRange(volume);
  if (!range)
    throw Error("no voxel has a finite intensity");
  // ITK's bounds for a float sample: the margin from the float difference, the top raised by it.
  const double lower = range->first;
  const double margin = static_cast<double>(range->second - range->first) / bins / 100.0;
  const double upper = static_cast<double>(range->second) + margin;

  auto histogram = IntensityHistogram::New();
  IntensityHistogram::SizeType size(1);
  size.Fill(bins);
  IntensityHistogram::MeasurementVectorType lowerBound(1), upperBound(1);
  lowerBound.Fill(lower);
  upperBound.Fill(upper);
  histogram->SetMeasurementVectorSize(1);
  histogram->Initialize(size, lowerBound, upperBound);

  const float* voxel = volume->GetBufferPointer();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  IntensityHistogram::MeasurementVectorType measurement(1);
  IntensityHistogram::IndexType index(1);
  for (std::size_t n = 0; n < count; ++n)
    if (std::isfinite(voxel[n]))
    {
      measurement[0] = voxel[n];
      histogram->GetIndex(measurement, index);
      if (!histogram->IsIndexOutOfBounds(index))
        histogram->IncreaseFrequencyOfIndex(index, 1);
    }
  return histogram;
}

} // namespace slicemesh

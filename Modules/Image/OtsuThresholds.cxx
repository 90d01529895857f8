// Multiple Otsu thresholds from ITK's histogram generator and calculator.
#include "OtsuThresholds.h"

#include "FiniteHistogram.h"

#include "Core/SliceMeshTypes.h"

#include "itkOtsuMultipleThresholdsCalculator.h"

namespace slicemesh
{
namespace
{

/** The bins of the histogram the thresholds are searched in: 256, fewer where the calculator's
 *  search would not end. It tries every way to place `count` thresholds between the bins, about
 *  C(bins, count) of them (20 ns each here): four thresholds in 256 bins take 3.5 s, five would take
 *  minutes. Past four the bins are as many as keep that under 5e7 (92 for five, 38 for eight). */
unsigned int histogramBins(unsigned int count)
{
  if (count <= 4)
    return 256;
  const auto placements = [count](unsigned int bins)
  {
    double ways = 1.0;
    for (unsigned int i = 0; i < count; ++i)
      ways = ways * static_cast<double>(bins - i) / static_cast<double>(i + 1);
    return ways;
  };
  unsigned int bins = 256;
  while (bins > count + 1 && placements(bins) > 5e7)
    --bins;
  return bins;
}

} // namespace

std::vector<double> otsuThresholds(const ScalarVolume* volume, unsigned int count)
{
  if (count == 0)
    throw Error("Otsu: the number of thresholds must be at least 1");
  const auto range = finiteIntensityRange(volume);
  if (!range)
    throw Error("no voxel has a finite intensity (every one is NaN or infinite); Otsu's thresholds separate nothing");
  if (range->first == range->second)
    throw Error("every voxel has the same value; Otsu's thresholds separate nothing");

  using Calculator = itk::OtsuMultipleThresholdsCalculator<IntensityHistogram>;
  auto calculator = Calculator::New();
  calculator->SetInputHistogram(finiteIntensityHistogram(volume, histogramBins(count)));
  calculator->SetNumberOfThresholds(count);
  calculator->Compute();
  const auto& thresholds = calculator->GetOutput();
  return std::vector<double>(thresholds.begin(), thresholds.end());
}

} // namespace slicemesh

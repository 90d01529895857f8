// Multiple Otsu thresholds from ITK's histogram generator and calculator.
#include "OtsuThresholds.h"

#include "FiniteHistogram.h"

#include "Core/SliceMeshTypes.h"

#include "itkOtsuMultipleThresholdsCalculator.h"

namespace slicemesh
{

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
  calculator->SetInputHistogram(finiteIntensityHistogram(volume, 256));
  calculator->SetNumberOfThresholds(count);
  calculator->Compute();
  const auto& thresholds = calculator->GetOutput();
  return std::vector<double>(thresholds.begin(), thresholds.end());
}

} // namespace slicemesh

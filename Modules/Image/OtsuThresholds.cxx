// Multiple Otsu thresholds from ITK's histogram generator and calculator.
#include "OtsuThresholds.h"

#include "Core/SliceMeshTypes.h"

#include "itkOtsuMultipleThresholdsCalculator.h"
#include "itkScalarImageToHistogramGenerator.h"

namespace slicemesh
{

std::vector<double> otsuThresholds(const ScalarVolume* volume, unsigned int count)
{
  if (count == 0)
    throw Error("Otsu: the number of thresholds must be at least 1");
  const float* voxel = volume->GetBufferPointer();
  const std::size_t voxels = volume->GetBufferedRegion().GetNumberOfPixels();
  bool uniform = true;
  for (std::size_t n = 1; n < voxels && uniform; ++n)
    uniform = voxel[n] == voxel[0];
  if (uniform)
    throw Error("every voxel has the same value; Otsu's thresholds separate nothing");

  using HistogramGenerator = itk::Statistics::ScalarImageToHistogramGenerator<ScalarVolume>;
  auto histogramGenerator = HistogramGenerator::New();
  histogramGenerator->SetInput(volume);
  histogramGenerator->SetNumberOfBins(256);
  histogramGenerator->Compute();

  using Calculator = itk::OtsuMultipleThresholdsCalculator<HistogramGenerator::HistogramType>;
  auto calculator = Calculator::New();
  calculator->SetInputHistogram(histogramGenerator->GetOutput());
  calculator->SetNumberOfThresholds(count);
  calculator->Compute();
  const auto& thresholds = calculator->GetOutput();
  return std::vector<double>(thresholds.begin(), thresholds.end());
}

} // namespace slicemesh

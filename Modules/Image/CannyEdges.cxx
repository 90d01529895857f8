// Canny edge detection (ITK), per slice or in 3D.
#include "CannyEdges.h"

#include "PerSliceFilter.h"
#include "Core/SliceMeshTypes.h"

#include "itkCannyEdgeDetectionImageFilter.h"

namespace slicemesh
{
namespace
{

template <typename ImageType>
typename ImageType::Pointer canny(const ImageType* image, const CannyOptions& options)
{
  auto filter = itk::CannyEdgeDetectionImageFilter<ImageType, ImageType>::New();
  filter->SetInput(image);
  filter->SetVariance(options.variance);
  filter->SetLowerThreshold(options.lowerThreshold);
  filter->SetUpperThreshold(options.upperThreshold);
  filter->Update();
  typename ImageType::Pointer output = filter->GetOutput();
  output->DisconnectPipeline();
  return output;
}

} // namespace

MaskVolume::Pointer cannyEdges(const ScalarVolume* volume, const CannyOptions& options, ProcessingDimension dimension)
{
  if (!(options.variance >= 0.0) || !(options.lowerThreshold >= 0.0) ||
      !(options.upperThreshold >= options.lowerThreshold))
    throw Error("Canny edges: need variance >= 0 and 0 <= lower threshold <= upper threshold");
  if (dimension == ProcessingDimension::Volume3D)
  {
    const ScalarVolume::Pointer edges = canny<ScalarVolume>(volume, options);
    auto mask = MaskVolume::New();
    mask->CopyInformation(volume);
    mask->SetRegions(volume->GetBufferedRegion());
    mask->Allocate();
    const float* in = edges->GetBufferPointer();
    unsigned char* out = mask->GetBufferPointer();
    for (std::size_t n = 0, count = volume->GetBufferedRegion().GetNumberOfPixels(); n < count; ++n)
      out[n] = in[n] > 0.0f ? 1 : 0;
    return mask;
  }
  MaskVolume::Pointer mask = filterEachSlice<MaskVolume>(
    volume, [&](const SliceImage2D* slice) { return canny<SliceImage2D>(slice, options); });
  unsigned char* out = mask->GetBufferPointer();
  for (std::size_t n = 0, count = volume->GetBufferedRegion().GetNumberOfPixels(); n < count; ++n)
    out[n] = out[n] ? 1 : 0;
  return mask;
}

} // namespace slicemesh

// Denoising with ITK's recursive Gaussian and curvature anisotropic diffusion, per slice or in 3D.
#include "ImageDenoising.h"

#include "PerSliceFilter.h"

#include "itkCurvatureAnisotropicDiffusionImageFilter.h"
#include "itkSmoothingRecursiveGaussianImageFilter.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{
namespace
{

template <typename ImageType>
typename ImageType::Pointer gaussian(const ImageType* image, double sigma)
{
  auto filter = itk::SmoothingRecursiveGaussianImageFilter<ImageType, ImageType>::New();
  filter->SetInput(image);
  filter->SetSigma(sigma); // physical units (mm): the filter uses the image spacing
  filter->Update();
  typename ImageType::Pointer output = filter->GetOutput();
  output->DisconnectPipeline();
  return output;
}

template <typename ImageType>
typename ImageType::Pointer diffusion(const ImageType* image, unsigned int iterations, double conductance)
{
  constexpr unsigned int d = ImageType::ImageDimension;
  double minSpacing = image->GetSpacing()[0];
  for (unsigned int a = 1; a < d; ++a)
    minSpacing = std::min(minSpacing, image->GetSpacing()[a]);
  auto filter = itk::CurvatureAnisotropicDiffusionImageFilter<ImageType, ImageType>::New();
  filter->SetInput(image);
  filter->SetNumberOfIterations(iterations);
  filter->SetConductanceParameter(conductance);
  filter->SetTimeStep(minSpacing / std::pow(2.0, d + 1.0));
  filter->Update();
  typename ImageType::Pointer output = filter->GetOutput();
  output->DisconnectPipeline();
  return output;
}

template <typename ImageType>
typename ImageType::Pointer denoise(const ImageType* image, const DenoisingOptions& options)
{
  typename ImageType::Pointer current = const_cast<ImageType*>(image);
  if (options.gaussianSigma > 0.0)
    current = gaussian<ImageType>(current, options.gaussianSigma);
  if (options.diffusionIterations > 0)
    current = diffusion<ImageType>(current, options.diffusionIterations, options.diffusionConductance);
  return current;
}

} // namespace

ScalarVolume::Pointer denoiseVolume(const ScalarVolume* volume, const DenoisingOptions& options)
{
  if (!options.any())
    return const_cast<ScalarVolume*>(volume);
  if (options.dimension == ProcessingDimension::Volume3D)
    return denoise<ScalarVolume>(volume, options);
  return filterEachSlice<ScalarVolume>(volume,
                                       [&](const SliceImage2D* slice) { return denoise<SliceImage2D>(slice, options); });
}

} // namespace slicemesh

// Widening a stored volume to float, voxel for voxel, as ITK's reader converts a file's pixels.
#include "StoredVolume.h"

namespace slicemesh
{

const itk::ImageBase<3>* imageOf(const StoredVolume& volume)
{
  return std::visit([](const auto& image) -> const itk::ImageBase<3>* { return image.GetPointer(); }, volume);
}

ScalarVolume::Pointer floatVolumeOf(const StoredVolume& volume)
{
  if (const auto* asFloat = std::get_if<ScalarVolume::Pointer>(&volume))
    return *asFloat;
  return std::visit(
    [](const auto& image)
    {
      auto widened = ScalarVolume::New();
      widened->CopyInformation(image);
      widened->SetRegions(image->GetBufferedRegion());
      widened->Allocate();
      const auto* in = image->GetBufferPointer();
      const std::size_t count = image->GetBufferedRegion().GetNumberOfPixels();
      float* out = widened->GetBufferPointer();
      for (std::size_t n = 0; n < count; ++n)
        out[n] = static_cast<float>(in[n]);
      return widened;
    },
    volume);
}

} // namespace slicemesh

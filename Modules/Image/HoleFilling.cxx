// Hole filling: background components that do not touch the border are holes.
#include "HoleFilling.h"

namespace slicemesh
{

std::size_t fillHoles(MaskVolume* mask, ProcessingDimension dimension)
{
  const ComponentLabels background = labelComponents(mask, dimension, 0, true);
  const auto size = mask->GetBufferedRegion().GetSize();
  const long nx = static_cast<long>(size[0]), ny = static_cast<long>(size[1]), nz = static_cast<long>(size[2]);
  const bool in3D = dimension == ProcessingDimension::Volume3D;

  std::vector<unsigned char> reachesBorder(static_cast<std::size_t>(background.count) + 1, 0);
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
      {
        const bool border = i == 0 || j == 0 || i == nx - 1 || j == ny - 1 || (in3D && (k == 0 || k == nz - 1));
        if (border)
          reachesBorder[background.labels[(k * ny + j) * nx + i]] = 1;
      }

  unsigned char* out = mask->GetBufferPointer();
  std::size_t filled = 0;
  for (std::size_t n = 0; n < background.labels.size(); ++n)
  {
    const std::int32_t label = background.labels[n];
    if (label != 0 && !reachesBorder[label])
    {
      out[n] = 1;
      ++filled;
    }
  }
  return filled;
}

} // namespace slicemesh

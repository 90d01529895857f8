// Connected-component labelling by breadth-first flood fill in raster order (deterministic).
#include "ComponentLabeling.h"

#include <array>

namespace slicemesh
{

ComponentLabels labelComponents(const MaskVolume* mask, ProcessingDimension dimension, unsigned char value, bool wide)
{
  const auto size = mask->GetBufferedRegion().GetSize();
  const long nx = static_cast<long>(size[0]), ny = static_cast<long>(size[1]), nz = static_cast<long>(size[2]);
  const unsigned char* in = mask->GetBufferPointer();
  const bool in3D = dimension == ProcessingDimension::Volume3D;

  // Neighbour offsets (di, dj, dk).
  std::vector<std::array<int, 3>> offsets;
  for (int dk = in3D ? -1 : 0; dk <= (in3D ? 1 : 0); ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
      {
        const int nonZero = (di != 0) + (dj != 0) + (dk != 0);
        if (nonZero == 0 || (!wide && nonZero > 1))
          continue;
        offsets.push_back({ di, dj, dk });
      }

  ComponentLabels result;
  result.labels.assign(static_cast<std::size_t>(nx * ny * nz), 0);
  std::vector<long> queue;
  for (long start = 0; start < nx * ny * nz; ++start)
  {
    if (in[start] != value || result.labels[start] != 0)
      continue;
    const std::int32_t label = ++result.count;
    result.labels[start] = label;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
      const long n = queue[head];
      const long i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
      for (const auto& o : offsets)
      {
        const long a = i + o[0], b = j + o[1], c = k + o[2];
        if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz)
          continue;
        const long m = (c * ny + b) * nx + a;
        if (in[m] != value || result.labels[m] != 0)
          continue;
        result.labels[m] = label;
        queue.push_back(m);
      }
    }
  }
  return result;
}

} // namespace slicemesh

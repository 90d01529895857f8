#include "SliceSmoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slicemesh
{
namespace
{

std::vector<float> gaussianKernel(double sigma, double spacing)
{
  const long radius = gaussianRadius(sigma, spacing);
  std::vector<float> kernel(2 * radius + 1);
  double sum = 0.0;
  for (long i = -radius; i <= radius; ++i)
  {
    const double x = i * spacing / sigma;
    sum += kernel[i + radius] = static_cast<float>(std::exp(-0.5 * x * x));
  }
  for (float& k : kernel)
    k = static_cast<float>(k / sum);
  return kernel;
}

/** One 1D pass along lines of `count` samples `stride` apart; `lines` lines `lineStride` apart. */
void convolve(float* pixels, long count, long stride, long lines, long lineStride, const std::vector<float>& kernel)
{
  const long radius = static_cast<long>(kernel.size() / 2);
  std::vector<float> line(count);
  for (long l = 0; l < lines; ++l)
  {
    float* start = pixels + l * lineStride;
    for (long i = 0; i < count; ++i)
      line[i] = start[i * stride];
    for (long i = 0; i < count; ++i)
    {
      double value = 0.0;
      const long from = std::max(-radius, -i), to = std::min(radius, count - 1 - i);
      for (long k = from; k <= to; ++k)
        value += kernel[k + radius] * line[i + k];
      start[i * stride] = static_cast<float>(value);
    }
  }
}

} // namespace

long gaussianRadius(double sigma, double spacing)
{
  if (!(sigma > 0.0) || !(spacing > 0.0))
    return 0;
  return static_cast<long>(std::ceil(3.0 * sigma / spacing));
}

void smoothSlice(float* pixels, long width, long height, double spacingX, double spacingY, double sigma)
{
  if (!(sigma > 0.0) || width <= 0 || height <= 0)
    return;
  convolve(pixels, width, 1, height, width, gaussianKernel(sigma, spacingX));
  convolve(pixels, height, width, width, 1, gaussianKernel(sigma, spacingY));
}

} // namespace slicemesh

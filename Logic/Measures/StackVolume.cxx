#include "Measures/StackVolume.h"

#include "Contours/ContourNesting.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

double sliceThickness(const ContourStack& stack, std::size_t k)
{
  // Half the gap to each neighbour; beyond an end slice, half the slice spacing (or, without one,
  // half the gap on the other side). A slice missing inside the stack is shared by its neighbours,
  // as the tiling bridges it.
  const std::vector<Slice>& slices = stack.slices;
  const double below = k > 0 ? slices[k].z - slices[k - 1].z : 0.0;
  const double above = k + 1 < slices.size() ? slices[k + 1].z - slices[k].z : 0.0;
  const double beyond = stack.sliceSpacing > 0.0 ? stack.sliceSpacing : std::max(below, above);
  return 0.5 * ((k > 0 ? below : beyond) + (k + 1 < slices.size() ? above : beyond));
}

double prismVolume(const ContourStack& stack)
{
  const std::vector<Slice>& slices = stack.slices;
  double volume = 0.0;
  for (std::size_t k = 0; k < slices.size(); ++k)
  {
    const double thickness = sliceThickness(stack, k);
    std::vector<Polygon2> contours = slices[k].contours;
    const ContourNesting nesting = orientAndNest(contours);
    double area = 0.0;
    for (std::size_t c = 0; c < contours.size(); ++c)
      area += (nesting.isHole(c) ? -0.5 : 0.5) * std::abs(twiceSignedArea(contours[c]));
    volume += area * thickness;
  }
  return volume;
}

} // namespace slicemesh

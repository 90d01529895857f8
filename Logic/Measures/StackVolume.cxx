#include "Measures/StackVolume.h"

#include "Contours/ContourNesting.h"
#include "Core/PlanarGeometry.h"

#include <cmath>

namespace slicemesh
{

double prismVolume(const ContourStack& stack)
{
  const std::vector<Slice>& slices = stack.slices;
  double volume = 0.0;
  for (std::size_t k = 0; k < slices.size(); ++k)
  {
    double thickness = stack.sliceSpacing;
    if (!(thickness > 0.0))
    {
      const double below = k > 0 ? slices[k].z - slices[k - 1].z : 0.0;
      const double above = k + 1 < slices.size() ? slices[k + 1].z - slices[k].z : 0.0;
      thickness = below > 0.0 && above > 0.0 ? 0.5 * (below + above) : below + above;
    }
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

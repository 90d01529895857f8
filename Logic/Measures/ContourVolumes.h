// Each contour's share of the volume a stack stands for, and where the contour lies: so that every
// connected piece of a surface can be given the volume of its own contours, not a share of the whole.
#ifndef ContourVolumes_h
#define ContourVolumes_h

#include "Core/SliceMeshTypes.h"

#include <array>
#include <vector>

namespace slicemesh
{

struct ContourVolume
{
  Point3 point;        ///< a point of the contour, at its slice's height
  double volume = 0.0; ///< its area, a hole's negative, times its slice's thickness (mm^3)
};

/** One share per contour of the stack, holes told by nesting. Without `pixel`, a contour's area is
 *  its polygon's and the slice's thickness prismVolume's (StackVolume.h): the shares add up to
 *  prismVolume. With `pixel` (the sides of a mask's pixels along x and y, mm), for contours traced
 *  from the mask in its stack frame (pixel centres at whole multiples of the sides), the area is
 *  that of the pixel centres inside the contour and the thickness the stack's slice spacing: a
 *  traced contour separates the mask's pixels from the others, so the shares are the mask's own
 *  voxels and add up to its volume. A voxel is traced as a diamond of half its area: by areas, a
 *  speck of a few voxels would get half of its voxels' share or less. */
std::vector<ContourVolume> contourVolumes(const ContourStack& stack, const std::array<double, 2>& pixel = { 0.0, 0.0 });

} // namespace slicemesh

#endif

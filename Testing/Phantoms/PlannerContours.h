// A phantom contoured as a treatment planning system draws it: one closed polygon per piece of each
// axial slice, its points on the shape's true outline at irregular steps along it. The input of the
// contour path's accuracy checks, whose truth is the phantom's distance function.
#ifndef PlannerContours_h
#define PlannerContours_h

#include "Phantom.h"
#include "Core/SliceMeshTypes.h"

#include <random>
#include <vector>

namespace slicemesh
{

/** The phantom's contours (mm, each a closed polygon in its slice's plane) on axial slices
 *  `sliceSpacing` apart, placed off the shape's centre as CT slices fall (the first 0.37 of a
 *  spacing above its lower bound); their points about `pointSpacing` apart, each step's position
 *  moved by up to 35% of a step by `random` (as a planner clicks or a tool resamples). The same
 *  generator state gives the same contours. */
std::vector<std::vector<Point3>> plannerContours(const Phantom& phantom, double sliceSpacing, double pointSpacing,
                                                 std::mt19937& random);

} // namespace slicemesh

#endif

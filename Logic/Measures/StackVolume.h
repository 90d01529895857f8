// The volume a stack of contours stands for, counted as voxels and planning systems count it.
#ifndef StackVolume_h
#define StackVolume_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Each slice's area (inside its outer contours, outside their holes; holes told by nesting, not by
 *  winding) times its thickness, summed (mm^3): the volume of the voxels a mask's traced contours
 *  came from, and the volume a planning system gives a structure set's ROI, whose end slices reach
 *  half a slice beyond their contours. The thickness is the stack's slice spacing, or, when that is
 *  0, the mean of the gaps to the neighbouring slices. */
double prismVolume(const ContourStack& stack);

} // namespace slicemesh

#endif

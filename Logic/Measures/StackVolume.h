// The volume a stack of contours stands for, counted as voxels and planning systems count it.
#ifndef StackVolume_h
#define StackVolume_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** Each slice's area (inside its outer contours, outside their holes; holes told by nesting, not by
 *  winding) times its thickness, summed (mm^3): the volume of the voxels a mask's traced contours
 *  came from, and the volume a planning system gives a structure set's ROI, whose end slices reach
 *  half a slice beyond their contours. A slice's thickness is half the gap to each neighbour, and
 *  half the stack's slice spacing beyond an end slice (half the one gap when the spacing is 0): on
 *  evenly spaced slices, the slice spacing; a slice missing inside the stack is shared by its two
 *  neighbours, as the tiling bridges it. */
double prismVolume(const ContourStack& stack);

/** The thickness prismVolume gives slice k (mm). */
double sliceThickness(const ContourStack& stack, std::size_t k);

} // namespace slicemesh

#endif

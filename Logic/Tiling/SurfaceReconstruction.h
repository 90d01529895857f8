// The tiling (Documentation/Algorithm.md, steps 3-8): a stack of slice contours in, a closed triangle
// surface out, every contour vertex on its slice.
#ifndef SurfaceReconstruction_h
#define SurfaceReconstruction_h

#include "Tiling/TilingOptions.h"

namespace slicemesh
{

/** The distance within which points of the stack's slices are one point: `asked`
 *  (ReconstructionOptions::mergeTolerance), or ten of the contours' coordinate steps
 *  (ContourStack::coordinateStep) where that is larger and at most 0.01 mm. */
double mergeToleranceFor(const ContourStack& stack, double asked);

/** Reconstructs the closed surface bounded by the contours of the stack.
 *  Contours may come in any orientation; they are oriented and nested first. Points closer than
 *  mergeToleranceFor(stack, options.mergeTolerance) are one point.
 *  Throws slicemesh::Error on input it cannot mesh. */
TriangleMesh reconstructSurface(const ContourStack& stack,
                                const ReconstructionOptions& options = {},
                                ReconstructionStatistics* statistics = nullptr);

} // namespace slicemesh

#endif

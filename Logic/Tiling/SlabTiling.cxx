// The tiling of one slab, step by step (Documentation/Algorithm.md, steps 4-8): the order of the
// steps; each lives in its own file (SlabOverlayState.h lists them).
#include "Tiling/SlabTiling.h"

#include "Tiling/SlabOverlayState.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

SlabOverlay::SlabOverlay(const PreparedSlice* lower, const PreparedSlice* upper, double z0, double z1,
                         double tolerance)
  : m_Impl(std::make_unique<Impl>())
{
  Impl& d = *m_Impl;
  d.lower = lower && !lower->contours.empty() ? lower : nullptr;
  d.upper = upper && !upper->contours.empty() ? upper : nullptr;
  d.z0 = z0;
  d.z1 = z1;
  d.tolerance = tolerance;
  d.lowerContinues.assign(d.lower ? d.lower->contours.size() : 0, 0);
  d.upperContinues.assign(d.upper ? d.upper->contours.size() : 0, 0);
  if (!d.lower && !d.upper)
    return; // nothing to tile between two empty slices
  d.buildVertices();
  d.buildEdges();
  d.triangulate();
  d.classify();
}

SlabOverlay::~SlabOverlay() = default;

const std::vector<char>& SlabOverlay::lowerContinues() const
{
  return m_Impl->lowerContinues;
}

const std::vector<char>& SlabOverlay::upperContinues() const
{
  return m_Impl->upperContinues;
}

const std::vector<std::pair<int, int>>& SlabOverlay::correspondences() const
{
  return m_Impl->correspondences;
}

void SlabOverlay::lift(MeshBuilder& mesh, const SlabLiftOptions& options, ReconstructionStatistics& statistics)
{
  Impl& d = *m_Impl;
  if (d.vertices.empty())
    return;
  d.liftOptions = &options;
  d.computeCapHeights();
  const double dz = d.z1 - d.z0;
  const int rows = std::max(1, static_cast<int>(std::lround(dz / options.rowHeight)));

  // Rows first: the flat-chord splits then fall on the few chords the rows leave.
  if (options.minAngleDegrees > 0.0)
  {
    const double edgeLength = options.maxEdgeLength > 0.0 ? options.maxEdgeLength : options.rowHeight;
    statistics.steinerPoints += d.addRows(mesh, edgeLength);
    statistics.steinerPoints += d.addCapRows(mesh, edgeLength);
    statistics.steinerPoints += d.liftFlatChords(mesh);
    const std::size_t budget = 20 * d.vertices.size() + 100;
    if (options.surfaceMetricFlips)
      d.flipTowardsSurfaceQuality(mesh);
    statistics.steinerPoints += d.refineBadTriangles(mesh, options.minAngleDegrees * M_PI / 180.0, edgeLength, budget);
  }
  const std::size_t lastChords = d.liftFlatChords(mesh);
  statistics.steinerPoints += lastChords;
  // The flips after each round of the refinement leave every edge where no flip improves it (a
  // point's insertion changes only the faces around it, which they look at): a last pass over every
  // edge is needed only where chords were split since, or a pass stopped at its limit. Up to
  // rounding: an edge is judged from one of its two faces, and at a threshold the other side can
  // decide otherwise. (The pass never flipped an edge on the benchmark structure set's 386 slabs
  // or the thick ellipsoid's 88.)
  if (options.minAngleDegrees > 0.0 && options.surfaceMetricFlips && (lastChords > 0 || !d.flipsSettled))
    d.flipTowardsSurfaceQuality(mesh);

  d.emitTriangles(mesh, rows, statistics);
}

} // namespace slicemesh

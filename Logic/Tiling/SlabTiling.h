// Stage: the surface between two adjacent slices (one slab), by the paper's modified difference
// polygons: the projections of the two slices are overlaid, their symmetric difference is
// triangulated by a constrained Delaunay triangulation (CDT) and lifted back to 3D.
#ifndef SlabTiling_h
#define SlabTiling_h

#include "Contours/ContourNesting.h"
#include "Tiling/MeshBuilder.h"
#include "Tiling/TilingOptions.h"

#include <memory>

namespace slicemesh
{

/** The oriented, nested contours of one slice and the mesh ids of their vertices. */
struct PreparedSlice
{
  double z = 0.0;
  std::vector<Polygon2> contours;
  ContourNesting nesting;
  std::vector<std::int32_t> firstVertexId; ///< mesh id of each contour's first vertex
};

struct SlabLiftOptions
{
  double rowHeight = 1.0;                        ///< target height of a row of wall triangles (mm)
  CapPlacement capPlacement = CapPlacement::HalfSliceBeyond;
  double minAngleDegrees = 30.0;                 ///< Steiner refinement target on the 3D triangles; 0: off
  double maxEdgeLength = 0.0;                    ///< Steiner spacing (mm); 0: the row height
  bool surfaceMetricFlips = true;                ///< flip towards 3D quality after refinement
  const std::vector<char>* lowerIsolated = nullptr; ///< lower contours whose region meets neither neighbour
  const std::vector<char>* upperIsolated = nullptr;
};

/** The overlay of two adjacent slices; either may be missing (the slab beyond the first or last
 *  slice, or next to an empty slice), which leaves only caps. Contours must already meet only at
 *  common vertices (insertMutualIntersections). */
class SlabOverlay
{
public:
  SlabOverlay(const PreparedSlice* lower, const PreparedSlice* upper, double z0, double z1, double tolerance);
  ~SlabOverlay();
  SlabOverlay(const SlabOverlay&) = delete;
  SlabOverlay& operator=(const SlabOverlay&) = delete;

  /** Per lower contour: whether its region (inside for an outer boundary, the hole for a hole)
   *  overlaps a region of the same kind in the upper slice — the correspondence of the paper. */
  const std::vector<char>& lowerContinues() const;
  const std::vector<char>& upperContinues() const;

  /** Pairs (lower outer contour, upper outer contour) whose regions overlap. */
  const std::vector<std::pair<int, int>>& correspondences() const;

  /** Tiles the slab: difference polygons, walls of coincident contours, caps; appends to the mesh. */
  void lift(MeshBuilder& mesh, const SlabLiftOptions& options, ReconstructionStatistics& statistics);

private:
  struct Impl;
  std::unique_ptr<Impl> m_Impl;
};

} // namespace slicemesh

#endif

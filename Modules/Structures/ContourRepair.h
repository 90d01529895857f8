// Contours drawn by hand or by a planning system, made into what the tiling takes: per slice,
// contours that neither cross nor touch, keyholes split into an outer contour and its hole.
#ifndef ContourRepair_h
#define ContourRepair_h

#include "Core/SliceMeshTypes.h"

#include <string>
#include <vector>

namespace slicemesh
{

struct ContourRepairOptions
{
  /** Channels narrower than this (mm) are closed: a keyhole's cut into its hole, two contours this
   *  close. */
  double channelWidth = 0.1;
};

/** What repairing a stack did. */
struct ContourRepairReport
{
  std::vector<double> crossingSlices; ///< z of the slices whose contours crossed (mm)
  /** z of the slices whose contours only touched (keyholes) or where narrow channels were closed (mm). */
  std::vector<double> channelSlices;
  bool any() const { return !crossingSlices.empty() || !channelSlices.empty(); }
  /** One line, e.g. "contours crossing in 2 slices (z = 3, 6 mm) repaired by the even-odd rule;
   *  keyholes (...), touching contours or channels under 0.1 mm split or closed in 1 slice (z = 9
   *  mm)"; empty when none. */
  std::string summary(double channelWidth) const;
};

/** The region the contours of one slice enclose, by the even-odd rule (a point is inside when an
 *  odd number of contours surround it: holes by nesting depth, never by winding), as contours
 *  that neither cross nor touch, with channels narrower than the width closed. A polygon boolean
 *  of Clipper; each contour of the result a little over 1 micrometre inside the region's boundary
 *  where pieces met at a point. */
std::vector<Polygon2> evenOddRegion(const std::vector<Polygon2>& contours, const ContourRepairOptions& options = {});

/** Every slice whose contours cross or touch, or where closing the narrow channels changes how
 *  many contours there are (a keyhole), replaced by its evenOddRegion; the other slices are kept
 *  exactly as they were. Slices with a proper crossing are reported as crossing, the others
 *  (touching, keyholes, narrow channels) as channels. */
ContourStack repairContours(const ContourStack& stack, const ContourRepairOptions& options = {},
                            ContourRepairReport* report = nullptr);

} // namespace slicemesh

#endif

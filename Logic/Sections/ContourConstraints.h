// Constraints for a variational implicit function from slice contours (Turk & O'Brien 2002,
// "normal constraints"; Carr et al. 2001, "off-surface points").
//
// On every contour, f = 0 at points spread evenly along arc length; beside each such point, at a
// distance delta along the in-plane normal, f = +delta outside and f = -delta inside. The normal
// pairs fix the gradient, and so the sign, of f: the solid is where f < 0.
#ifndef ContourConstraints_h
#define ContourConstraints_h

#include "Sections/VariationalImplicit.h"

namespace slicemesh
{

struct ConstraintSampling
{
  /** Budget of centres over all slices (each sample gives up to three). A dense solve of n centres
   *  costs O(n^3): 600 centres solve in a few tens of milliseconds whatever the contours' size,
   *  because contours of thousands of points are subsampled evenly along their arc length. */
  std::size_t maxCentres = 600;
  /** Each contour keeps at least this many samples, even if the budget is then exceeded a little;
   *  three when the contours are too many for that to fit the budget. */
  std::size_t minSamplesPerContour = 8;
  /** Offset of the off-surface pairs along the normal, as a fraction of the sample spacing. */
  double normalOffsetFraction = 0.5;
};

struct ConstraintSummary
{
  std::size_t onSurface = 0;
  std::size_t offSurface = 0;
  std::size_t droppedOffSurface = 0; ///< offset points that fell on the wrong side (thin parts)
  double sampleSpacing = 0.0;        ///< mm along the contours
  double normalOffset = 0.0;         ///< delta, mm
};

/** Constraints from the contours of the given slices. Contours may come in any orientation (each slice
 *  is nested first: outer boundaries and holes get normals pointing out of the solid). An offset
 *  point that does not land on its side of the slice's region (a thin part) is dropped. Throws Error
 *  for more contours than even three samples each would keep within three times the budget. */
std::vector<ImplicitConstraint> contourConstraints(const std::vector<Slice>& slices,
                                                   const ConstraintSampling& sampling = {},
                                                   ConstraintSummary* summary = nullptr);

} // namespace slicemesh

#endif

// Steps 6 and 7 of Documentation/Algorithm.md: the heights of points inside a slab (the distance-ratio
// interpolant) and of the caps (domes half a slice beyond the last contour).
#include "Tiling/SlabOverlayState.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicemesh
{

using namespace slab;

double SlabOverlay::Impl::interpolatedHeight(const Point2& p) const
{
  // Distance-ratio interpolation between the two contours (the linear blend of their distance
  // transforms): 0 on the lower contour, 1 on the upper one.
  const double dLower = lowerNearest->distance(p);
  const double dUpper = upperNearest->distance(p);
  // Kept strictly inside the slab: a point lifted exactly onto a slice plane (a Steiner point a
  // rounding error away from a contour) could lie flat against the neighbouring slab's triangles.
  const double t = dLower + dUpper > 0.0 ? dLower / (dLower + dUpper) : 0.5;
  return z0 + std::clamp(t, 1e-3, 1.0 - 1e-3) * (z1 - z0);
}

void SlabOverlay::Impl::computeCapHeights()
{
  capZ.assign(components.size(), std::numeric_limits<double>::quiet_NaN());
  if (!liftOptions)
    return;
  // The height a cap's dome reaches: half a slice beyond the last contour by default; a contour that
  // meets neither neighbour gets that thickness even when caps sit on their slice.
  const double dz = z1 - z0;
  const double baseOffset = liftOptions->capPlacement == CapPlacement::HalfSliceBeyond ? 0.5 * dz : 0.0;
  std::vector<char> needsThickness(components.size(), 0);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!isCapFace(f))
      continue;
    const Component& c = components[f->info().component];
    for (int i = 0; i < 3; ++i)
    {
      if (!f->is_constrained(i))
        continue;
      const OverlayEdge* e = edgeBetween(f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i)));
      const std::vector<char>* isolated =
        c.capLevel() == LowerLevel ? liftOptions->lowerIsolated : liftOptions->upperIsolated;
      const int contour = c.capLevel() == LowerLevel ? e->lowerContour : e->upperContour;
      if (isolated && contour >= 0 && static_cast<std::size_t>(contour) < isolated->size() && (*isolated)[contour])
        needsThickness[f->info().component] = 1;
    }
  }
  for (std::size_t c = 0; c < components.size(); ++c)
  {
    if (!components[c].isCap())
      continue;
    const double offset = needsThickness[c] ? 0.5 * dz : baseOffset;
    capZ[c] = components[c].capLevel() == LowerLevel ? z0 + offset : z1 - offset;
  }
}

Point3 SlabOverlay::Impl::approximateLift(FaceHandle f, int i, const MeshBuilder& mesh) const
{
  const OverlayVertex& v = vertices[f->vertex(i)->info()];
  if (v.isSteiner())
    return mesh.point(v.steinerId);
  if (isCapFace(f))
    return { v.p.x, v.p.y, capLevelZ(f->info().component) };
  if (v.onBoth())
  {
    const signed char level = f->info().cornerLevel[i];
    return { v.p.x, v.p.y, level == LowerLevel ? z0 : level == UpperLevel ? z1 : 0.5 * (z0 + z1) };
  }
  return { v.p.x, v.p.y, v.lowerId >= 0 ? z0 : z1 };
}

double SlabOverlay::Impl::domeHeight(int component, const Point2& p) const
{
  // A cap is a dome over its contour: it leaves the contour's slice and, within a distance equal to
  // its height, reaches the cap height (half a slice beyond by default) on a quarter-circle profile,
  // the rounded end a smooth structure has and the voxels' extent in the middle.
  const double base = capLevelZ(component);
  const double rise = capZ[component] - base;
  if (rise == 0.0)
    return base;
  const NearestSegment& rim = components[component].capLevel() == LowerLevel ? *lowerNearest : *upperNearest;
  const double s = std::min(1.0, rim.distanceWithin(p, std::abs(rise)) / std::abs(rise)); // 1 from |rise| on
  // Never flat on the contour's own slice, where the neighbouring slab's triangles meet it.
  return base + rise * std::max(1e-3, std::sqrt(1.0 - (1.0 - s) * (1.0 - s)));
}

} // namespace slicemesh

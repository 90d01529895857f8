// The angles of a triangle in 3D: the one place the stages measure them (the validation's and the
// quality measures' statistics, the tiling's Steiner refinement and flips).
#ifndef TriangleAngles_h
#define TriangleAngles_h

#include "Core/SliceMeshTypes.h"

#include <array>

namespace slicemesh
{

/** The angles of triangle abc at a, b and c (radians), each from the cross and dot products of its
 *  two edges, atan2(|u x v|, u . v): accurate for slivers and for angles near 180 degrees alike. */
std::array<double, 3> triangleAngles(const Point3& a, const Point3& b, const Point3& c);

/** The smallest angle of triangle abc (radians). */
double smallestAngle(const Point3& a, const Point3& b, const Point3& c);

/** The largest angle of triangle abc (radians). */
double largestAngle(const Point3& a, const Point3& b, const Point3& c);

/** Whether an angle (radians) lies under a bound (degrees) by more than the rounding of its
 *  computation. A corner that is the bound exactly (30 degrees comes out of half-voxel coordinates
 *  on isotropic grids, as between (1, 0.5, 0.5) and (0.5, 0.5, 0)) is not under it, whichever way the
 *  last bit of its computed value fell. */
bool angleUnder(double radians, double boundDegrees);

/** The cosine of the smallest angle of triangle abc, the one opposite its shortest edge, without
 *  inverse trigonometry (for counts over whole meshes); 1, an angle of 0, for a triangle without area. */
double smallestAngleCosine(const Point3& a, const Point3& b, const Point3& c);

/** How far apart two smallest-angle cosines must lie for them to decide a comparison of the
 *  angles: far above either's rounding, and an angle moves at least as much as its cosine, so two
 *  angles whose cosines differ by more differ by more too (by more than any margin under it).
 *  Nearer, a comparison falls back on the angles themselves (smallestAngle). */
constexpr double smallestAngleCosineTie = 1e-7;

/** A lower bound on a triangle's smallest angle. metBy(a, b, c) is smallestAngle(a, b, c) >= the
 *  bound, decided by the angle's cosine unless it lies within smallestAngleCosineTie of the
 *  bound's: the same answers, mostly without an arc tangent. */
class SmallestAngleBound
{
public:
  explicit SmallestAngleBound(double radians);
  bool metBy(const Point3& a, const Point3& b, const Point3& c) const;

private:
  double m_Radians;
  double m_Cosine;
};

} // namespace slicemesh

#endif

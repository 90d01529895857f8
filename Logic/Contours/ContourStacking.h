// Planar contours given in 3-D (an ROI of a structure set, a contour file) as a contour stack: the
// slice normal found from the contours themselves, the contours sorted into slices along it, and
// the stack frame that puts the stack back exactly where the contours were.
#ifndef ContourStacking_h
#define ContourStacking_h

#include "Core/SliceMeshTypes.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace slicemesh
{

/** A closed planar contour in 3-D (mm); the last point connects back to the first. */
using Polygon3 = std::vector<Point3>;

using Vector3 = std::array<double, 3>;

/** Newell's normal of a closed polygon: its direction is the plane's normal (right-handed with the
 *  winding), its length twice the enclosed area; robust to a few points off the plane. */
Vector3 newellNormal(const Polygon3& contour);

/** The normal of the plane a closed contour spans: newellNormal, unless the contour crosses itself
 *  so that its lobes' windings cancel it (a symmetric figure eight); then the sum of the triangles
 *  from its centroid to its edges, each turned to agree with the largest (its length then twice
 *  the lobes' area). */
Vector3 planeNormal(const Polygon3& contour);

struct ContourStackingOptions
{
  /** The slice direction of the image the contours were drawn on, when known (any length, either
   *  sign); empty: the contours' own normal (sliceNormalOf). When the contours' own normal is further
   *  than maxNormalDeviationDegrees from it, they are not on that image's slices and their own
   *  normal is used (StackedContours::normalDeviationDegrees says so). */
  std::optional<Vector3> sliceNormal;
  double maxNormalDeviationDegrees = 1.0;
  /** The slice spacing of that image (mm); 0: none known. Unless the contours are off its slices
   *  (their normal is not sliceNormal), it is the stack's spacing when they lie in one slice or two
   *  of their slices are one image slice apart (within 5%), or their median gap is three or more
   *  image slices (a whole number, within 5%), so that gaps are counted in the image's slices;
   *  otherwise the contours' median gap is (a note says so). */
  double expectedSliceSpacing = 0.0;
  /** Contours whose own normal is further than this from the slice normal are skipped (degrees). */
  double maxTiltDegrees = 10.0;
  /** Contours closer than this along the normal share a slice (mm); 0: a quarter of the median gap
   *  over 0.05 mm between contour positions (the slice spacing), at most 0.25 mm. */
  double sliceTolerance = 0.0;
  /** The slice spacing when the contours cannot tell it (all in one slice); 0: none known. */
  double fallbackSliceSpacing = 0.0;
  /** With no image spacing known (expectedSliceSpacing), the slice spacing of the set the contours
   *  belong to, where the set shows one clearly; 0: none. A structure whose own gaps are three or
   *  more of these slices (a whole number, within 5%) is drawn on the set's slices and stops and
   *  starts again between them, as it does when the image's spacing is known; it is not a structure
   *  of slices that far apart. */
  double setSliceSpacing = 0.0;
  /** Resample spacing in the slice plane (mm); 0: automaticPointSpacing of the stack. */
  double pointSpacing = 0.0;
};

/** The contours as a stack, and what had to be done to get there. */
struct StackedContours
{
  /** Slices at the positions along the normal, x and y in the in-plane basis (mm). sliceSpacing is
   *  the usual gap between slices: the thickness each slice stands for. */
  ContourStack stack;
  /** origin + direction * (x, y, z) is the patient position of a stack point; the direction's
   *  columns are the in-plane basis and the normal (orthonormal, right-handed). spacing is `spacing`. */
  SliceFrame frame;
  /** In-plane point spacing (twice) and slice spacing: the grid the meshing options are resolved for. */
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  std::size_t contoursUsed = 0;
  /** With options.sliceNormal: the angle between it and the contours' own normal (degrees), and
   *  whether the stack follows it (the angle is within options.maxNormalDeviationDegrees). */
  std::optional<double> normalDeviationDegrees;
  bool givenNormalUsed = false;
  /** One line each: contours skipped (tilted, no area), duplicates dropped, gaps bridged or left
   *  open, uneven spacing. */
  std::vector<std::string> notes;
};

/** The slice normal of the contours: the area-weighted mean of the Newell normals that agree with
 *  the largest contour's, signed so that its largest component is positive. Throws Error when no
 *  contour encloses an area. */
Vector3 sliceNormalOf(const std::vector<Polygon3>& contours);

/** The resample spacing in the slice plane for planar contours (mm): the stack's slice spacing
 *  (the tiling's walls get near-equilateral triangles), at most a 64th of the median contour's
 *  perimeter (small structures keep their shape), at least 0.5 mm. */
double automaticPointSpacing(const ContourStack& stack);

/** About how many triangles the tiling of `stack` makes with its contours resampled `pointSpacing`
 *  apart: between two neighbouring slices with contours, rows about a point spacing high from one
 *  to the other, two triangles per point and row; a cap per point. For a check before the tiling:
 *  a gap is tiled whole, so the tiling grows with its height (two contours of one ROI a kilometre
 *  apart make a wall a kilometre high), which nothing else in the input bounds. */
double estimatedTilingTriangles(const ContourStack& stack, double pointSpacing);

/** The step the contours' coordinates were rounded to where they were written (mm): 10^-d for the
 *  fewest decimals d up to 9 of which they are all whole multiples (a DICOM decimal string: 1e-6
 *  for six decimals); else, if every one is a single-precision number (3D Slicer's planar contours),
 *  that precision's spacing at the largest of them; else 0 (not rounded). */
double coordinateStep(const std::vector<Polygon3>& contours);

/** Sorts the contours into slices along the normal (options.sliceNormal when the contours lie on
 *  its planes, else sliceNormalOf):
 *  contours within the slice tolerance share a slice; a contour repeated in its slice is dropped;
 *  a gap of one missing slice is tiled across, a longer gap leaves empty slices so the pieces on
 *  either side are closed on their own; the stack's coordinateStep is coordinateStep(contours). Throws
 *  Error when no contour is left or when all lie in one slice and no spacing is known. */
StackedContours stackContours(const std::vector<Polygon3>& contours, const ContourStackingOptions& options = {});

} // namespace slicemesh

#endif

// How traced contours are shaped before tiling: smoothed or kept as traced, simplified, resampled.
#ifndef ContourPreparation_h
#define ContourPreparation_h

#include "Core/SliceMeshTypes.h"

#include <array>

namespace slicemesh
{

/** How the traced contours are shaped before tiling. */
enum class ContourPreparation
{
  Automatic, ///< Smoothed when the slices are at least twice as thick as the pixels, else Traced
  Smoothed,  ///< Taubin smoothing, then resampling (to the point spacing, or the automatic one)
  Traced     ///< the traced contours (resampled only to an explicit point spacing)
};

struct ContourPreparationOptions
{
  ContourPreparation mode = ContourPreparation::Traced; ///< the best-shaped triangles on every grid measured
  int smoothingIterations = 30;         ///< Taubin lambda/mu pairs (Smoothed); 0: no smoothing
  double smoothingMaxShift = 0.0;       ///< bound on each point's move (mm); 0: 0.3 of the smaller pixel side
  double simplificationTolerance = 0.0; ///< Douglas-Peucker tolerance, crossing-free (mm); 0: none
  double simplificationMaxEdge = 0.0;   ///< no simplified edge longer than this where points allow (mm); 0: any
  double pointSpacing = 0.0;            ///< resample to this spacing (mm); 0: automatic (see resolved)
  /** Drawn contours (a structure set's): resampled keeping their corners and every point on the
   *  drawn polyline (resampleContourKeepingCorners), not keeping their area. Traced contours are a
   *  staircase, whose corners are not the anatomy's. */
  bool keepCorners = false;
};

/** The options with every automatic value replaced by its value for a grid of this spacing (x, y,
 *  slice; mm): the mode Automatic by Smoothed or Traced; for smoothed contours the shift bound by
 *  0.3 of the smaller pixel side and the point spacing by the geometric mean of the smaller pixel
 *  side and the slice spacing (thick slices get fewer, longer contour edges); for traced contours a
 *  point spacing of 0 stays 0: the traced points are kept. */
ContourPreparationOptions resolvedContourPreparation(const ContourPreparationOptions& options,
                                                     const std::array<double, 3>& spacing);

/** The contours as the tiling takes them, with resolved options: smoothed (ContourSmoothing.h) when
 *  the mode is Smoothed, simplified (ContourSimplification.h), resampled to the point spacing
 *  keeping each contour's area, or with keepCorners its corners (ContourResampling.h), all
 *  crossing-free. */
ContourStack prepareContours(const ContourStack& traced, const ContourPreparationOptions& resolved);

} // namespace slicemesh

#endif

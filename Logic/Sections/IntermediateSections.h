// Stage (before reconstructSurface): intermediate sections for undersampled slabs, from the zero
// level set of a variational implicit function (paper, section 4.4; Turk & O'Brien 1999/2002).
//
// A slab (two adjacent slices) gets sections when
//  - bridging is on and a pair of its contours corresponds only by distance (no overlap): the
//    sections carry the shape across, so the pair becomes one component of the surface; or
//  - refineWeakOverlap is on and a pair overlaps by less than sectionOverlap of the smaller region; or
//  - its slice spacing exceeds maxSliceSpacingFactor times the in-plane spacing.
// Spacing only: one implicit function is fitted to all contours of the slab's two slices and of the
// slices just beyond them (for smoothness across slabs); each section is its zero level set at one
// height, extracted by marching squares over the slab's box plus a margin.
// Bridging (and weak overlap): one function per correspondence group, fitted in a frame sheared along
// the group's drift (the centroid displacement from slice to slice), so the pair overlaps itself in
// that frame; a single unsheared fit cannot bridge: its zero level set keeps each contour as a
// vertical column (measured: f > 0 half way between two circles 1.5 diameters apart). Sections are
// added until consecutive layers of every group overlap by sectionOverlap of the smaller region (the
// paper stops at any overlap; the tiling of partly overlapping contours loses volume).
// Every fit compresses z so that the slab is no thicker than half its contours' thickness: thin-plate
// interpolation across a slab much thicker than the shape bulges or pinches between the slices.
// Sections are kept only if they connect, by overlap, exactly the contours the correspondence rule
// joins (no component added or removed; a one-to-one pair keeps one contour per section) and the
// contours of a section stay apart; otherwise the slab is left as it was and a note says so.
#ifndef IntermediateSections_h
#define IntermediateSections_h

#include "Sections/ContourConstraints.h"
#include "Core/SliceMeshTypes.h"

#include <string>
#include <vector>

namespace slicemesh
{

struct UndersamplingOptions
{
  /** Threshold of the distance rule (mm): same-orientation contours of adjacent slices whose
   *  boundaries come closer than this correspond even without overlap. 0: overlap only. */
  double correspondenceDistance = 0.0;
  /** Join distance-matched, non-overlapping contours through intermediate sections (paper 4.4).
   *  Off by default, as in the paper; needs correspondenceDistance > 0 to have any effect. */
  bool bridgeNonOverlapping = false;
  /** 0: off. Otherwise slabs thicker than this factor times the in-plane spacing (the median contour
   *  edge length of the stack) get evenly spaced sections until they are not. */
  double maxSliceSpacingFactor = 0.0;
  /** Bridged slabs get sections until consecutive layers of every group overlap by at least this
   *  share of the smaller region. The paper asks only that they overlap (0), but the tiling between
   *  partly overlapping contours loses volume, the more so the smaller the overlap (measured for an
   *  ellipse 5.85 x 2 mm sliding along its long axis, mean area across the slab: overlap 0.38 -23%,
   *  0.57 -11%, 0.78 -3%, 0.89 -1%). The loss is the construction's, not the triangulation's: the
   *  exact blend of the two contours' distance functions loses as much (mid-slab area 83% at 0.57),
   *  since no such blend turns a shape into a translated copy; sections that follow the drift do. */
  double sectionOverlap = 0.8;
  /** Also give sections (from the same per-group fits) to slabs in which corresponding contours do
   *  overlap, but by less than sectionOverlap: a structure that slides along its length between
   *  slices, like a tube at a shallow angle to them. Off by default. */
  bool refineWeakOverlap = false;
  /** Most sections inserted into one slab. */
  std::size_t maxSectionsPerSlab = 16;
  /** The budget of centres per fit (see ContourConstraints.h). */
  ConstraintSampling sampling;
};

struct SectionStatistics
{
  std::size_t slabs = 0;             ///< slabs examined
  std::size_t slabsFitted = 0;       ///< slabs for which an implicit function was fitted
  std::size_t slabsRefined = 0;      ///< slabs that got sections
  std::size_t slabsBridged = 0;      ///< slabs whose distance-only pairs are now joined by overlapping sections
  std::size_t slabsOverlapRefined = 0; ///< slabs of partly overlapping pairs given sections (refineWeakOverlap)
  std::size_t bridgesFailed = 0;     ///< slabs whose distance-only pairs could not be joined within the cap
  std::size_t slabsRejected = 0;     ///< slabs whose sections changed the topology and were dropped
  std::size_t sectionsInserted = 0;
  double smallestSectionOverlap = 1.0; ///< least overlap share of consecutive layers in slabs given per-group sections
  std::size_t largestFit = 0;        ///< centres in the largest fit
  double fitSeconds = 0.0;           ///< building and solving the implicit functions
  double extractSeconds = 0.0;       ///< evaluating grids and extracting and checking sections
  double inPlaneSpacing = 0.0;       ///< the median contour edge length (mm)
  std::vector<std::string> notes;    ///< one line per slab that could not be handled as asked
};

/** Returns the stack with intermediate sections inserted where the options ask for them; slices not
 *  touched are copied unchanged, sections come between them in increasing z. Throws slicemesh::Error
 *  on bad options (negative or non-finite values). */
ContourStack insertIntermediateSections(const ContourStack& stack, const UndersamplingOptions& options,
                                        SectionStatistics* statistics = nullptr);

} // namespace slicemesh

#endif

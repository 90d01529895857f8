// Stage: which contours of two adjacent slices belong to the same piece of surface.
//
// The distance rule of the paper (section 4.1): two contours of the same orientation (outer boundary
// with outer boundary, hole with hole) correspond when, projected onto one plane, their regions
// overlap or their boundaries come closer than a threshold. The groups are the connected components
// of that correspondence graph: one-to-one, one-to-many (branching), many-to-one, many-to-many.
#ifndef ContourCorrespondence_h
#define ContourCorrespondence_h

#include "Core/SliceMeshTypes.h"

#include <cstddef>
#include <vector>

namespace slicemesh
{

enum class ContactKind
{
  Overlap,       ///< the regions share area
  WithinDistance ///< no shared area, but the boundaries come closer than the threshold
};

/** One edge of the correspondence graph: contour `lower` of the lower slice with `upper` of the upper. */
struct ContourLink
{
  std::size_t lower = 0;
  std::size_t upper = 0;
  ContactKind contact = ContactKind::Overlap;
  double distance = 0.0; ///< boundary distance (mm) for WithinDistance links; 0 for overlaps
};

enum class GroupShape
{
  OneToOne,
  OneToMany,  ///< one lower contour, several upper ones: a branching going up
  ManyToOne,  ///< several lower contours merge into one upper contour
  ManyToMany,
  LowerOnly,  ///< a lower contour with no partner: its component ends here (a cap)
  UpperOnly   ///< an upper contour with no partner: a component starts here
};

enum class GroupContact
{
  None,           ///< an unmatched contour
  Overlap,        ///< every link is an overlap
  WithinDistance, ///< no link overlaps: the members only lie within the threshold
  Mixed           ///< some links overlap, some only lie within the threshold
};

/** A connected component of the correspondence graph; all members have the same orientation. */
struct CorrespondenceGroup
{
  bool holes = false;              ///< true for a group of holes, false for outer boundaries
  std::vector<std::size_t> lower;  ///< contour indices in the lower slice, increasing
  std::vector<std::size_t> upper;  ///< contour indices in the upper slice, increasing
  std::vector<ContourLink> links;

  GroupShape shape() const;
  GroupContact contact() const;
  bool hasDistanceOnlyLink() const;
};

struct SlabCorrespondence
{
  /** Groups with lower contours first, in order of their smallest lower index, then upper-only
   *  groups in order of their upper index (deterministic). */
  std::vector<CorrespondenceGroup> groups;
  std::size_t overlapTests = 0;  ///< contour pairs whose regions were tested (after the box filter)
  std::size_t distanceTests = 0; ///< contour pairs whose boundary distance was measured
};

/** Matches the contours of two adjacent slices by the distance rule. Contours may come in any
 *  orientation: each slice is nested first (outer boundaries at even depth, holes at odd depth).
 *  distanceThreshold (mm) 0 means overlap only. Contours with fewer than three points belong to no
 *  group. Throws slicemesh::Error on a negative or non-finite threshold. */
SlabCorrespondence matchContours(const std::vector<Polygon2>& lower, const std::vector<Polygon2>& upper,
                                 double distanceThreshold = 0.0);

const char* toString(GroupShape shape);
const char* toString(GroupContact contact);

} // namespace slicemesh

#endif

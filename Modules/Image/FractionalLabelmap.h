// 3D Slicer's fractional labelmap: a segment's layer holds, for each voxel, how much of it the
// segment fills (Slicer counts 216 shifted binary samples, stored as signed char from -108 to 108).
// SliceMesh meshes a segment where the fraction is at least one half, the threshold Slicer's own
// fractional-labelmap-to-surface conversion uses by default: the layer becomes a label map of that
// one segment (value 1), as a binary segment's layer is, and goes the same way from there.
#ifndef FractionalLabelmap_h
#define FractionalLabelmap_h

#include "VolumeReader.h"

#include <array>
#include <string>

namespace slicemesh
{

/** The values a fractional layer spans (Slicer's "ScalarRange"): `minimum` is an empty voxel,
 *  `maximum` a full one. */
struct FractionalRange
{
  double minimum = -108.0;
  double maximum = 108.0;
  /** A voxel is in the segment when its value is at least this: minimum + 0.5 (maximum - minimum). */
  double half() const { return this->minimum + 0.5 * (this->maximum - this->minimum); }
};

/** The range of Slicer's fractional labelmaps (its signed char voxels): used when a file gives none. */
constexpr FractionalRange slicerFractionalRange{ -108.0, 108.0 };

/** "min max": a range field's text. Throws slicemesh::Error naming the file and field when it is
 *  not two finite numbers with min < max. */
FractionalRange fractionalRangeField(const std::string& path, const std::string& key, const std::string& text);

/** The voxels a segment may have, as Slicer's SegmentN_Extent gives them: the first and last i, the
 *  first and last j, the first and last k, as indices of the file's voxels. Empty when a first is
 *  past its last (Slicer's "0 -1 0 -1 0 -1" of an empty segment). */
using VoxelExtent = std::array<long, 6>;

/** "i0 i1 j0 j1 k0 k1": an extent field's text. Throws slicemesh::Error naming the file and field
 *  when it is not six integers. */
VoxelExtent voxelExtentField(const std::string& path, const std::string& key, const std::string& text);

/** The whole of a layer. */
VoxelExtent wholeExtent(const ScalarVolume* layer);

/** Turns `layer`, one segment's fractions, into that segment's label map in place: 1 where the
 *  voxel lies in `extent` and its value is at least range.half(), 0 elsewhere. Throws
 *  slicemesh::Error, one line starting with `what`, when a voxel's value lies outside the range
 *  (the layer is not of that range: a different voxel type or scale). */
void thresholdFractionalLayer(ScalarVolume* layer, const FractionalRange& range, const VoxelExtent& extent,
                              const std::string& what);

} // namespace slicemesh

#endif

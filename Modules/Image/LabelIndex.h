// One pass over a label map: every label's voxel count and bounding box, then a mask per label
// cropped to its box, so N labels cost one scan plus the boxes, not N scans of the volume.
#ifndef LabelIndex_h
#define LabelIndex_h

#include "VolumeReader.h"

#include <array>
#include <vector>

namespace slicemesh
{

struct LabelExtent
{
  int label = 0;
  std::size_t voxels = 0;
  std::array<long, 3> lower{ 0, 0, 0 }; ///< smallest index of the label's voxels (inclusive)
  std::array<long, 3> upper{ 0, 0, 0 }; ///< largest index (inclusive)
};

/** Whether negative whole values are labels. ITK and 3D Slicer label maps may be signed images, and
 *  a volume given as a label map (--inputKind LabelMap) has its negative values meshed as labels;
 *  otherwise a negative voxel means the volume is no label map (a CT's Hounsfield units). */
enum class NegativeLabels
{
  Refused,
  Allowed
};

/** The non-zero labels of the volume in increasing order, each with its voxel count and index
 *  box. Throws slicemesh::Error when a voxel is not an integer in [0, 2^31), or in [-2^31, 2^31)
 *  with negative labels allowed (not a label map). TImage: ScalarVolume, or a label map in the
 *  pixel type of its file (any image of StoredVolume). */
template <typename TImage>
std::vector<LabelExtent> indexLabels(const TImage* labelMap, NegativeLabels negative = NegativeLabels::Refused);

/** The mask (1 where the voxel equals extent.label) of the label's box: an image whose region
 *  starts at the box's index, with the label map's spacing, origin and direction, so physical
 *  points and Logic's stack frame (sliceFrameOf) place it where it is in the full volume. TImage
 *  as for indexLabels. */
template <typename TImage>
MaskVolume::Pointer cropLabelMask(const TImage* labelMap, const LabelExtent& extent);

/** The two above for an image held by a smart pointer. */
template <typename TImage>
std::vector<LabelExtent> indexLabels(const itk::SmartPointer<TImage>& labelMap,
                                     NegativeLabels negative = NegativeLabels::Refused)
{
  return indexLabels(labelMap.GetPointer(), negative);
}
template <typename TImage>
MaskVolume::Pointer cropLabelMask(const itk::SmartPointer<TImage>& labelMap, const LabelExtent& extent)
{
  return cropLabelMask(labelMap.GetPointer(), extent);
}

} // namespace slicemesh

#endif

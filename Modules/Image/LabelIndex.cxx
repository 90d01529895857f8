// Label bounding boxes in one raster pass; per-label cropping.
#include "LabelIndex.h"

#include "Core/ParallelFor.h"
#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <type_traits>

namespace slicemesh
{
namespace
{

/** Whether a non-zero voxel value is no label: fractional, not finite, beyond an int (2^31 or more,
 *  under -2^31), or negative unless negative labels are allowed. */
template <typename Pixel>
bool notALabel(Pixel value, NegativeLabels negative)
{
  if constexpr (std::is_signed_v<Pixel>)
    if (value < Pixel(0) && negative == NegativeLabels::Refused)
      return true;
  if constexpr (std::is_floating_point_v<Pixel>)
    return !(value >= -2147483648.0f && value < 2147483648.0f) || std::floor(value) != value; // NaN fails the first
  else
    return static_cast<std::int64_t>(value) >= 2147483648LL; // four unsigned bytes may pass a label's int
}

} // namespace

template <typename TImage>
std::vector<LabelExtent> indexLabels(const TImage* labelMap, NegativeLabels negative)
{
  using Pixel = typename TImage::PixelType;
  const auto region = labelMap->GetBufferedRegion();
  const auto size = region.GetSize();
  const auto start = region.GetIndex();
  const Pixel* voxel = labelMap->GetBufferPointer();
  std::map<int, LabelExtent> extents;
  // Most label maps have a few hundred labels at most: a table for the small ones, a map beyond.
  std::vector<LabelExtent> table(4096);
  for (long k = 0; k < static_cast<long>(size[2]); ++k)
    for (long j = 0; j < static_cast<long>(size[1]); ++j)
      for (long i = 0; i < static_cast<long>(size[0]); ++i, ++voxel)
      {
        const Pixel value = *voxel;
        if (value == Pixel(0))
          continue;
        if (notALabel(value, negative))
        {
          const double asDouble = static_cast<double>(value);
          const bool whole = std::isfinite(asDouble) && std::floor(asDouble) == asDouble;
          std::ostringstream message;
          message.precision(9); // a float's every digit: 1.0000001 is no label, "1" would say it is
          message << "voxel (" << i + start[0] << ", " << j + start[1] << ", " << k + start[2] << ") holds "
                  << +value;
          if (whole && asDouble > 0.0)
            message << ": a label above 2147483647, the largest SliceMesh names";
          else if (whole && negative == NegativeLabels::Allowed)
            message << ": a label below -2147483648, the smallest SliceMesh names";
          else if (whole)
            message << ": a negative value, which is a label only in a volume given with --inputKind LabelMap";
          else
            message << ": not a label map (labels are whole numbers)";
          throw Error(message.str());
        }
        const int label = static_cast<int>(value);
        // The common small labels in the table; negative and large ones in the map.
        LabelExtent& e = label >= 0 && label < static_cast<int>(table.size()) ? table[label] : extents[label];
        const std::array<long, 3> index{ i + start[0], j + start[1], k + start[2] };
        if (e.voxels++ == 0)
        {
          e.label = label;
          e.lower = e.upper = index;
          continue;
        }
        for (int a = 0; a < 3; ++a)
        {
          e.lower[a] = std::min(e.lower[a], index[a]);
          e.upper[a] = std::max(e.upper[a], index[a]);
        }
      }
  // In increasing order: the map's negative labels, the table's, the map's large ones.
  std::vector<LabelExtent> labels;
  auto beyond = extents.begin();
  for (; beyond != extents.end() && beyond->first < 0; ++beyond)
    labels.push_back(beyond->second);
  for (const LabelExtent& e : table)
    if (e.voxels)
      labels.push_back(e);
  for (; beyond != extents.end(); ++beyond)
    labels.push_back(beyond->second);
  return labels;
}

template <typename TImage>
MaskVolume::Pointer cropLabelMask(const TImage* labelMap, const LabelExtent& extent)
{
  using Pixel = typename TImage::PixelType;
  const auto region = labelMap->GetBufferedRegion();
  MaskVolume::IndexType index;
  MaskVolume::SizeType size;
  for (int a = 0; a < 3; ++a)
  {
    index[a] = extent.lower[a];
    size[a] = static_cast<std::size_t>(extent.upper[a] - extent.lower[a] + 1);
  }
  const MaskVolume::RegionType box(index, size);
  if (!region.IsInside(box))
    throw Error("cropLabelMask: the label's box lies outside the label map");

  auto mask = MaskVolume::New();
  mask->SetOrigin(labelMap->GetOrigin());
  mask->SetSpacing(labelMap->GetSpacing());
  mask->SetDirection(labelMap->GetDirection());
  mask->SetRegions(box);
  mask->Allocate();
  // A float label map compares as it always did; integers compare exactly.
  const Pixel wanted = static_cast<Pixel>(extent.label);
  const auto full = region.GetSize();
  // Slices side by side: the body of a whole-body segmentation is most of the volume, and its mask
  // was cut on one thread while the other cores waited.
  parallelForRanges(
    size[2], 0,
    [&](std::size_t firstSlice, std::size_t lastSlice)
    {
      unsigned char* out = mask->GetBufferPointer() + firstSlice * size[1] * size[0];
      for (std::size_t k = firstSlice; k < lastSlice; ++k)
        for (std::size_t j = 0; j < size[1]; ++j)
        {
          const std::size_t row =
            ((k + index[2] - region.GetIndex()[2]) * full[1] + (j + index[1] - region.GetIndex()[1])) * full[0] +
            (index[0] - region.GetIndex()[0]);
          const Pixel* in = labelMap->GetBufferPointer() + row;
          for (std::size_t i = 0; i < size[0]; ++i)
            *out++ = in[i] == wanted ? 1 : 0;
        }
    },
    /*minimumRange=*/std::max<std::size_t>(1, (std::size_t(1) << 20) / std::max<std::size_t>(1, size[0] * size[1])));
  return mask;
}

// Every image type a StoredVolume holds.
#define SLICEMESH_LABEL_INDEX(Pixel)                                                                         \
  template std::vector<LabelExtent> indexLabels(const itk::Image<Pixel, 3>*, NegativeLabels);                \
  template MaskVolume::Pointer cropLabelMask(const itk::Image<Pixel, 3>*, const LabelExtent&);
SLICEMESH_LABEL_INDEX(float)
SLICEMESH_LABEL_INDEX(std::uint8_t)
SLICEMESH_LABEL_INDEX(std::int8_t)
SLICEMESH_LABEL_INDEX(std::uint16_t)
SLICEMESH_LABEL_INDEX(std::int16_t)
SLICEMESH_LABEL_INDEX(std::uint32_t)
SLICEMESH_LABEL_INDEX(std::int32_t)
#undef SLICEMESH_LABEL_INDEX

} // namespace slicemesh

// A fractional layer thresholded at half its range, within the segment's extent.
#include "FractionalLabelmap.h"

#include "ItkErrorText.h"

#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slicemesh
{
namespace
{

std::string quoted(const std::string& text)
{
  const std::string line = collapsedWhitespace(text);
  return "'" + (line.size() > 60 ? line.substr(0, 57) + "..." : line) + "'";
}

} // namespace

FractionalRange fractionalRangeField(const std::string& path, const std::string& key, const std::string& text)
{
  std::istringstream in(text);
  FractionalRange range;
  std::string rest;
  if (!(in >> range.minimum >> range.maximum) || (in >> rest) || !std::isfinite(range.minimum) ||
      !std::isfinite(range.maximum) || range.minimum >= range.maximum)
    throw Error(path + ": header field " + key + " is " + quoted(text) +
                ", not a range of fractions (two numbers, the empty voxel's value below the full one's)");
  return range;
}

VoxelExtent voxelExtentField(const std::string& path, const std::string& key, const std::string& text)
{
  std::istringstream in(text);
  VoxelExtent extent{};
  std::string rest;
  for (long& bound : extent)
    if (!(in >> bound))
      throw Error(path + ": header field " + key + " is " + quoted(text) + ", not six integers (i0 i1 j0 j1 k0 k1)");
  if (in >> rest)
    throw Error(path + ": header field " + key + " is " + quoted(text) + ", not six integers (i0 i1 j0 j1 k0 k1)");
  return extent;
}

VoxelExtent wholeExtent(const ScalarVolume* layer)
{
  const ScalarVolume::RegionType region = layer->GetBufferedRegion();
  VoxelExtent extent{};
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    extent[2 * axis] = region.GetIndex()[axis];
    extent[2 * axis + 1] = region.GetIndex()[axis] + static_cast<long>(region.GetSize()[axis]) - 1;
  }
  return extent;
}

void thresholdFractionalLayer(ScalarVolume* layer, const FractionalRange& range, const VoxelExtent& extent,
                              const std::string& what)
{
  const ScalarVolume::RegionType region = layer->GetBufferedRegion();
  const std::array<long, 3> size{ static_cast<long>(region.GetSize()[0]), static_cast<long>(region.GetSize()[1]),
                                  static_cast<long>(region.GetSize()[2]) };
  // The extent clipped to the layer, in buffer offsets. Slicer pads a segment out to the file's
  // common box with 0, which is a half-full voxel of its -108..108 range: outside its extent a
  // voxel is not the segment's, whatever its value.
  std::array<long, 3> first{}, last{};
  for (int axis = 0; axis < 3; ++axis)
  {
    first[axis] = std::max(extent[2 * axis] - region.GetIndex()[axis], 0L);
    last[axis] = std::min(extent[2 * axis + 1] - region.GetIndex()[axis], size[axis] - 1);
  }
  const double half = range.half();
  float* voxel = layer->GetBufferPointer();
  for (long k = 0; k < size[2]; ++k)
    for (long j = 0; j < size[1]; ++j)
      for (long i = 0; i < size[0]; ++i, ++voxel)
      {
        const double value = *voxel;
        if (!(value >= range.minimum && value <= range.maximum))
        {
          std::ostringstream message;
          message << what << ": voxel (" << i << ", " << j << ", " << k << ") is " << value
                  << ", outside the fractional range " << range.minimum << " to " << range.maximum;
          throw Error(message.str());
        }
        const bool inExtent = i >= first[0] && i <= last[0] && j >= first[1] && j <= last[1] && k >= first[2] &&
                              k <= last[2];
        *voxel = inExtent && value >= half ? 1.0f : 0.0f;
      }
}

} // namespace slicemesh

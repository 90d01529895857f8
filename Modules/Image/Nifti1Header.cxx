// NIfTI-1 header fields, read directly: ITK's reader checks some of them too late (or not at all)
// and exposes only the orientation it chose.
#include "Nifti1Header.h"

#include "Core/Lowercase.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace slicemesh
{
namespace
{

bool isNiftiName(const std::string& path)
{
  return endsInAnyCase(path, ".nii") || endsInAnyCase(path, ".nii.gz") || endsInAnyCase(path, ".hdr") ||
         endsInAnyCase(path, ".hdr.gz");
}

/** The field of type T at `offset` of the header's bytes, byte-swapped when the file's order is not
 *  the host's. */
template <typename T>
T field(const unsigned char* bytes, std::size_t offset, bool swap)
{
  unsigned char value[sizeof(T)];
  std::memcpy(value, bytes + offset, sizeof(T));
  if (swap)
    std::reverse(value, value + sizeof(T));
  T result;
  std::memcpy(&result, value, sizeof(T));
  return result;
}

} // namespace

bool isNifti2(const std::string& path)
{
  if (!isNiftiName(path))
    return false;
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file)
    return false;
  unsigned char bytes[4];
  const int read = gzread(file, bytes, sizeof bytes);
  gzclose(file);
  return read == static_cast<int>(sizeof bytes) &&
         (field<std::int32_t>(bytes, 0, false) == 540 || field<std::int32_t>(bytes, 0, true) == 540);
}

std::optional<Nifti1Header> readNifti1Header(const std::string& path)
{
  if (!isNiftiName(path))
    return std::nullopt;
  gzFile file = gzopen(path.c_str(), "rb"); // reads plain files too
  if (!file)
    return std::nullopt;
  unsigned char bytes[348];
  const int read = gzread(file, bytes, sizeof bytes);
  gzclose(file);
  if (read != static_cast<int>(sizeof bytes))
    return std::nullopt;
  // sizeof_hdr is 348 in NIfTI-1, in the file's byte order: it tells that order too.
  bool swap = false;
  if (field<std::int32_t>(bytes, 0, false) != 348)
  {
    if (field<std::int32_t>(bytes, 0, true) != 348)
      return std::nullopt;
    swap = true;
  }
  Nifti1Header header;
  for (std::size_t i = 0; i < 8; ++i)
  {
    header.dim[i] = field<std::int16_t>(bytes, 40 + 2 * i, swap);
    header.pixdim[i] = field<float>(bytes, 76 + 4 * i, swap);
  }
  header.bitpix = field<std::int16_t>(bytes, 72, swap);
  header.voxOffset = field<float>(bytes, 108, swap);
  header.xyztUnits = bytes[123];
  header.qformCode = field<std::int16_t>(bytes, 252, swap);
  header.sformCode = field<std::int16_t>(bytes, 254, swap);
  for (std::size_t i = 0; i < header.quaternion.size(); ++i)
    header.quaternion[i] = field<float>(bytes, 256 + 4 * i, swap);
  for (std::size_t i = 0; i < header.sform.size(); ++i)
    header.sform[i] = field<float>(bytes, 280 + 4 * i, swap);
  return header;
}

} // namespace slicemesh

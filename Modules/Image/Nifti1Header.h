// The NIfTI-1 header fields SliceMesh reads itself, from one parser: the reader's checks (size,
// spacing, orientation) and the qform/sform warning look at the same bytes.
#ifndef Nifti1Header_h
#define Nifti1Header_h

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace slicemesh
{

/** The fields of a NIfTI-1 header, in the host's byte order whatever the file's. */
struct Nifti1Header
{
  std::array<std::int16_t, 8> dim{};
  std::int16_t bitpix = 0;   ///< bits per stored voxel, before any scl_slope / scl_inter scaling
  std::array<float, 8> pixdim{}; ///< pixdim[0] is qfac, pixdim[1..3] the spacing
  float voxOffset = 0.0f;    ///< where the voxels start
  std::uint8_t xyztUnits = 0; ///< the spatial unit in its low three bits: 1 metre, 2 mm, 3 micron (0 unknown)
  std::int16_t qformCode = 0, sformCode = 0;
  std::array<float, 6> quaternion{}; ///< quatern_b, c, d, then qoffset_x, y, z
  std::array<float, 12> sform{};     ///< srow_x, srow_y, srow_z
};

/** The header of a NIfTI-1 file, named .nii or .hdr (a pair's header), plain or gzip, in any case.
 *  Empty for another name, or when the file is shorter than a header or not NIfTI-1 (NIfTI-2):
 *  ITK then reads it, or says what is wrong with it. */
std::optional<Nifti1Header> readNifti1Header(const std::string& path);

/** Whether the file, named as NIfTI, is NIfTI-2 (a header of 540 bytes), which ITK 5.2 does not read. */
bool isNifti2(const std::string& path);

} // namespace slicemesh

#endif

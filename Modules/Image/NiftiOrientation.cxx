// NIfTI-1 header orientation fields, read directly (ITK exposes only the one it chose).
#include "NiftiOrientation.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace slicemesh
{
namespace
{

template <typename T>
T field(const unsigned char* header, std::size_t offset, bool swap)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, header + offset, sizeof(T));
  if (swap)
    std::reverse(bytes, bytes + sizeof(T));
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

bool isNiftiName(const std::string& path)
{
  auto ends = [&](const char* suffix)
  {
    const std::size_t n = std::strlen(suffix);
    if (path.size() < n)
      return false;
    std::string tail = path.substr(path.size() - n);
    std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
    return tail == suffix;
  };
  return ends(".nii") || ends(".nii.gz") || ends(".hdr") || ends(".hdr.gz");
}

} // namespace

std::optional<NiftiOrientation> readNiftiOrientation(const std::string& path)
{
  if (!isNiftiName(path))
    return std::nullopt;
  gzFile file = gzopen(path.c_str(), "rb"); // reads plain files too
  if (!file)
    return std::nullopt;
  unsigned char header[348];
  const int read = gzread(file, header, sizeof(header));
  gzclose(file);
  if (read != static_cast<int>(sizeof(header)))
    return std::nullopt;
  bool swap = false;
  if (field<std::int32_t>(header, 0, false) != 348)
  {
    swap = true;
    if (field<std::int32_t>(header, 0, true) != 348)
      return std::nullopt; // NIfTI-2 or not NIfTI
  }
  NiftiOrientation o;
  float pixdim[8];
  for (int i = 0; i < 8; ++i)
    pixdim[i] = field<float>(header, 76 + 4 * i, swap);
  o.qformCode = field<std::int16_t>(header, 252, swap);
  o.sformCode = field<std::int16_t>(header, 254, swap);
  double b = field<float>(header, 256, swap), c = field<float>(header, 260, swap), d = field<float>(header, 264, swap);
  const double qx = field<float>(header, 268, swap), qy = field<float>(header, 272, swap),
               qz = field<float>(header, 276, swap);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      o.sform[row][column] = field<float>(header, 280 + 16 * row + 4 * column, swap);

  // NIfTI-1 method 2: R from the quaternion (a >= 0 recovered), scaled by pixdim, qfac on the k column.
  // As nifti_quatern_to_mat44: a tiny remainder is rounding, and b, c, d are then normalized.
  double a = 1.0 - (b * b + c * c + d * d);
  if (a < 1e-7)
  {
    const double norm = std::sqrt(b * b + c * c + d * d);
    b /= norm, c /= norm, d /= norm;
    a = 0.0;
  }
  else
    a = std::sqrt(a);
  const double R[3][3] = { { a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c) },
                           { 2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b) },
                           { 2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - c * c - b * b } };
  const double qfac = pixdim[0] < 0 ? -1.0 : 1.0;
  const double scale[3] = { pixdim[1], pixdim[2], qfac * pixdim[3] };
  const double offset[3] = { qx, qy, qz };
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
      o.qform[row][column] = R[row][column] * scale[column];
    o.qform[row][3] = offset[row];
  }
  return o;
}

namespace
{

/** The largest distance (mm) between two voxel -> RAS maps over the corners of the volume. */
template <typename MapA, typename MapB>
double largestCornerDistance(const double size[3], MapA first, MapB second)
{
  double largest = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::array<double, 3> ijk{ (corner & 1) ? size[0] - 1 : 0.0, (corner & 2) ? size[1] - 1 : 0.0,
                                     (corner & 4) ? size[2] - 1 : 0.0 };
    const std::array<double, 3> p = first(ijk), q = second(ijk);
    largest = std::max(largest, std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                          (p[2] - q[2]) * (p[2] - q[2])));
  }
  return largest;
}

std::array<double, 3> apply(const Affine3x4& m, const std::array<double, 3>& ijk)
{
  std::array<double, 3> p{};
  for (int row = 0; row < 3; ++row)
    p[row] = m[row][0] * ijk[0] + m[row][1] * ijk[1] + m[row][2] * ijk[2] + m[row][3];
  return p;
}

} // namespace

std::optional<std::string> niftiOrientationWarning(const std::string& path, const itk::ImageBase<3>* volume,
                                                   double toleranceMm)
{
  const std::optional<NiftiOrientation> o = readNiftiOrientation(path);
  if (!o || o->qformCode <= 0 || o->sformCode <= 0 || !volume)
    return std::nullopt;
  const auto region = volume->GetLargestPossibleRegion();
  const double size[3] = { static_cast<double>(region.GetSize()[0]), static_cast<double>(region.GetSize()[1]),
                           static_cast<double>(region.GetSize()[2]) };
  const auto qform = [&](const std::array<double, 3>& ijk) { return apply(o->qform, ijk); };
  const auto sform = [&](const std::array<double, 3>& ijk) { return apply(o->sform, ijk); };
  const double disagreement = largestCornerDistance(size, qform, sform);
  if (disagreement <= toleranceMm)
    return std::nullopt;
  // The volume as read, in RAS (ITK's physical space is LPS).
  const auto asRead = [&](const std::array<double, 3>& ijk)
  {
    itk::ContinuousIndex<double, 3> index;
    for (int a = 0; a < 3; ++a)
      index[a] = ijk[a] + static_cast<double>(region.GetIndex()[a]);
    itk::Point<double, 3> p;
    volume->TransformContinuousIndexToPhysicalPoint(index, p);
    return std::array<double, 3>{ -p[0], -p[1], p[2] };
  };
  const double fromQform = largestCornerDistance(size, asRead, qform);
  const double fromSform = largestCornerDistance(size, asRead, sform);
  const char* used = fromSform <= toleranceMm   ? "the sform"
                     : fromQform <= toleranceMm ? "the qform"
                                                : "neither exactly (ITK made the sform orthonormal)";
  std::ostringstream message;
  message.precision(3);
  message << path << ": the NIfTI qform (code " << o->qformCode << ") and sform (code " << o->sformCode
          << ") disagree by up to " << std::fixed << disagreement << " mm at the volume's corners; using " << used
          << ", as ITK's NIfTI reader (and so 3D Slicer) does";
  return message.str();
}

} // namespace slicemesh

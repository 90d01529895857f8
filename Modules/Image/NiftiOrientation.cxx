// The two orientations of a NIfTI-1 header as voxel -> RAS maps (ITK exposes only the one it chose).
#include "NiftiOrientation.h"

#include "Nifti1Header.h"

#include "Core/Determinant3.h"
#include "Core/MeasureText.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slicemesh
{

std::optional<NiftiOrientation> readNiftiOrientation(const std::string& path)
{
  const std::optional<Nifti1Header> header = readNifti1Header(path);
  if (!header)
    return std::nullopt;
  NiftiOrientation o;
  o.qformCode = header->qformCode;
  o.sformCode = header->sformCode;
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t column = 0; column < 4; ++column)
      o.sform[row][column] = header->sform[4 * row + column];

  // NIfTI-1 method 2: R from the quaternion (a >= 0 recovered), scaled by pixdim, qfac on the k column.
  // As nifti_quatern_to_mat44: a tiny remainder is rounding, and b, c, d are then normalized.
  double b = header->quaternion[0], c = header->quaternion[1], d = header->quaternion[2];
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
  const std::array<float, 8>& pixdim = header->pixdim;
  const double qfac = pixdim[0] < 0 ? -1.0 : 1.0;
  const double scale[3] = { pixdim[1], pixdim[2], qfac * pixdim[3] };
  for (std::size_t row = 0; row < 3; ++row)
  {
    for (std::size_t column = 0; column < 3; ++column)
      o.qform[row][column] = R[row][column] * scale[column];
    o.qform[row][3] = header->quaternion[3 + row]; // qoffset_x, y, z
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

/** Where the two maps are mirror images of each other (one turns the voxel axes right-handed, the
 *  other left-handed): the RAS direction the mirror flips, as a reader would name it (the one that
 *  the sform's world axes map onto their opposites, by the product sform * qform^-1); empty if they
 *  are not mirrored. */
std::string mirroredDirection(const Affine3x4& qform, const Affine3x4& sform)
{
  const double dq = determinant3(qform), ds = determinant3(sform);
  if (!(dq * ds < 0.0))
    return {};
  // qform^-1 by cofactors; then the diagonal of sform * qform^-1: an axis flipped is near -1.
  double inverse[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
    {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      inverse[r][c] = (qform[r1][c1] * qform[r2][c2] - qform[r1][c2] * qform[r2][c1]) / dq;
    }
  int flipped = 0;
  double lowest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    double diagonal = 0.0;
    for (int k = 0; k < 3; ++k)
      diagonal += sform[a][k] * inverse[k][a];
    if (diagonal < lowest)
    {
      lowest = diagonal;
      flipped = a;
    }
  }
  static const char* const names[3] = { "left-right", "front-back", "head-foot" };
  return names[flipped];
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
  message << path << ": the NIfTI qform (code " << o->qformCode << ") and sform (code " << o->sformCode
          << ") disagree by up to " << measureText(disagreement, 3) << " mm at the volume's corners";
  // A side flip is the dangerous kind: FSL and MRIcron show the sform.
  const std::string mirrored = mirroredDirection(o->qform, o->sform);
  if (!mirrored.empty())
    message << " and are mirror images of each other (" << mirrored << ")";
  message << "; using " << used << ", as ITK's NIfTI reader (and so 3D Slicer) does";
  if (!mirrored.empty())
    message << " (FSL and MRIcron show the sform)";
  return message.str();
}

} // namespace slicemesh

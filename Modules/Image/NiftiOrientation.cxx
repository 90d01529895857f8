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
  const double b = field<float>(header, 256, swap), c = field<float>(header, 260, swap),
               d = field<float>(header, 264, swap);
  const double qx = field<float>(header, 268, swap), qy = field<float>(header, 272, swap),
               qz = field<float>(header, 276, swap);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      o.sform[row][column] = field<float>(header, 280 + 16 * row + 4 * column, swap);

  // NIfTI-1 method 2: R from the quaternion (a >= 0 recovered), scaled by pixdim, qfac on the k column.
  const double a = std::sqrt(std::max(0.0, 1.0 - (b * b + c * c + d * d)));
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

std::optional<std::string> niftiOrientationWarning(const std::string& path, double toleranceMm)
{
  const std::optional<NiftiOrientation> o = readNiftiOrientation(path);
  if (!o || o->qformCode <= 0 || o->sformCode <= 0)
    return std::nullopt;
  // Dimensions for the corners.
  gzFile in = gzopen(path.c_str(), "rb");
  unsigned char header[348];
  if (!in)
    return std::nullopt;
  const int read = gzread(in, header, sizeof(header));
  gzclose(in);
  if (read != 348)
    return std::nullopt;
  const bool swap = field<std::int32_t>(header, 0, false) != 348;
  double size[3];
  for (int i = 0; i < 3; ++i)
    size[i] = std::max<int>(1, field<std::int16_t>(header, 42 + 2 * i, swap));

  double largest = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double ijk[3] = { (corner & 1) ? size[0] - 1 : 0.0, (corner & 2) ? size[1] - 1 : 0.0,
                            (corner & 4) ? size[2] - 1 : 0.0 };
    double squared = 0.0;
    for (int row = 0; row < 3; ++row)
    {
      double q = o->qform[row][3], s = o->sform[row][3];
      for (int column = 0; column < 3; ++column)
      {
        q += o->qform[row][column] * ijk[column];
        s += o->sform[row][column] * ijk[column];
      }
      squared += (q - s) * (q - s);
    }
    largest = std::max(largest, std::sqrt(squared));
  }
  if (largest <= toleranceMm)
    return std::nullopt;

  // Which one ITK (and so 3D Slicer) takes: the sform when its 3x3 part is a rotation times the
  // voxel sizes (orthogonal columns), else the qform.
  bool sformRigid = true;
  for (int i = 0; i < 3 && sformRigid; ++i)
    for (int j = i + 1; j < 3; ++j)
    {
      double dot = 0.0, ni = 0.0, nj = 0.0;
      for (int row = 0; row < 3; ++row)
      {
        dot += o->sform[row][i] * o->sform[row][j];
        ni += o->sform[row][i] * o->sform[row][i];
        nj += o->sform[row][j] * o->sform[row][j];
      }
      if (std::abs(dot) > 1e-4 * std::sqrt(ni * nj))
        sformRigid = false;
    }
  std::ostringstream message;
  message.precision(3);
  message << path << ": the NIfTI qform (code " << o->qformCode << ") and sform (code " << o->sformCode
          << ") disagree by up to " << std::fixed << largest << " mm at the volume's corners; using the "
          << (sformRigid ? "sform" : "qform (the sform shears)") << ", as ITK and 3D Slicer do";
  return message.str();
}

} // namespace slicemesh

#include "ReaderSpaceCorrection.h"

#include "Core/Lowercase.h"

#include <algorithm>
#include <fstream>

namespace slicemesh
{
namespace
{

/** The value of a NRRD header's "space" field, in lower case; empty for another file or none. */
std::string nrrdSpace(const std::string& path)
{
  if (!endsInAnyCase(path, ".nrrd") && !endsInAnyCase(path, ".nhdr"))
    return {};
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD", 0) != 0)
    return {};
  // The header is text lines up to the first empty one; a NRRD header is a few hundred bytes, so
  // a bound on the lines read keeps a damaged file from being read whole here.
  for (int lines = 0; lines < 1000 && std::getline(in, line); ++lines)
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.empty())
      break;
    if (line.rfind("space:", 0) == 0)
    {
      const std::string value = lowercase(line.substr(6));
      const std::size_t first = value.find_first_not_of(" \t");
      return first == std::string::npos ? std::string() : value.substr(first, value.find_last_not_of(" \t") - first + 1);
    }
  }
  return {};
}

} // namespace

std::array<double, 3> ReaderSpaceCorrection::applied(const std::array<double, 3>& point, bool scaled) const
{
  const double scale = scaled ? this->originScale : 1.0;
  return { this->sign[0] * scale * point[0], this->sign[1] * scale * point[1], this->sign[2] * scale * point[2] };
}

ReaderSpaceCorrection readerSpaceCorrection(const std::string& path, const std::optional<Nifti1Header>& nifti)
{
  ReaderSpaceCorrection correction;
  const std::string space = nrrdSpace(path);
  if (space == "left-anterior-superior" || space == "las" || space == "left-anterior-superior-time" || space == "last")
    correction.sign = { -1.0, -1.0, 1.0 }; // ITK's (-x, y, z) of the file's axes, to (x, -y, z)
  if (nifti)
  {
    const int unit = nifti->xyztUnits & 0x07;
    if (unit == 1)
      correction.originScale = 1000.0; // metres
    else if (unit == 3)
      correction.originScale = 0.001; // microns
  }
  return correction;
}

void correctHeaderSpace(itk::ImageIOBase* io, const ReaderSpaceCorrection& correction)
{
  if (!correction.needed())
    return;
  const unsigned int axes = std::min(io->GetNumberOfDimensions(), 3u);
  std::array<double, 3> origin{ 0.0, 0.0, 0.0 };
  for (unsigned int axis = 0; axis < axes; ++axis)
    origin[axis] = io->GetOrigin(axis);
  origin = correction.applied(origin, true);
  for (unsigned int axis = 0; axis < axes; ++axis)
  {
    io->SetOrigin(axis, origin[axis]);
    std::vector<double> column = io->GetDirection(axis);
    std::array<double, 3> direction{ 0.0, 0.0, 0.0 };
    const std::size_t rows = std::min<std::size_t>(column.size(), 3);
    std::copy_n(column.begin(), rows, direction.begin());
    direction = correction.applied(direction, false);
    std::copy_n(direction.begin(), rows, column.begin());
    io->SetDirection(axis, column);
  }
}

} // namespace slicemesh

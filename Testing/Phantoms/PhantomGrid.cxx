#include "PhantomGrid.h"

#include "Core/AreaNormal.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace slicemesh
{

Vector3 GridSpec::physicalPoint(std::size_t i, std::size_t j, std::size_t k) const
{
  const Vector3 scaled(i * spacing[0], j * spacing[1], k * spacing[2]);
  return Vector3(origin[0], origin[1], origin[2]) + direction * scaled;
}

GridSpec gridAround(const Phantom& phantom, const std::array<double, 3>& spacing, int marginVoxels,
                    const Matrix3& direction)
{
  if (!(direction.transpose() * direction).isIdentity(1e-9))
    throw std::invalid_argument("gridAround: the direction matrix must be orthonormal");
  for (double s : spacing)
    if (!(s > 0.0) || !std::isfinite(s))
      throw std::invalid_argument("gridAround: the spacing must be positive");
  if (marginVoxels < 0)
    throw std::invalid_argument("gridAround: the margin must not be negative");

  // The shape's extent along each grid axis, from the corners of its axis-aligned bounds.
  const Bounds bounds = phantom.bounds();
  Vector3 lowest = Vector3::Constant(std::numeric_limits<double>::infinity());
  Vector3 highest = -lowest;
  for (int corner = 0; corner < 8; ++corner)
  {
    const Vector3 point((corner & 1) ? bounds.upper[0] : bounds.lower[0], (corner & 2) ? bounds.upper[1] : bounds.lower[1],
                        (corner & 4) ? bounds.upper[2] : bounds.lower[2]);
    const Vector3 alongAxes = direction.transpose() * point;
    lowest = lowest.cwiseMin(alongAxes);
    highest = highest.cwiseMax(alongAxes);
  }

  GridSpec grid;
  grid.spacing = spacing;
  grid.direction = direction;
  Vector3 start;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double span = highest[axis] - lowest[axis];
    const auto inner = static_cast<std::size_t>(std::ceil(span / spacing[axis])) + 1;
    grid.size[axis] = inner + 2 * static_cast<std::size_t>(marginVoxels);
    // Centre the samples on the shape so that the margin is the same on both sides.
    const double covered = (inner - 1) * spacing[axis];
    start[axis] = lowest[axis] - 0.5 * (covered - span) - marginVoxels * spacing[axis];
  }
  const Vector3 origin = direction * start;
  grid.origin = { origin[0], origin[1], origin[2] };
  return grid;
}

MaskVolume::Pointer rasterizePhantom(const Phantom& phantom, const GridSpec& grid)
{
  auto mask = MaskVolume::New();
  MaskVolume::SizeType size;
  MaskVolume::SpacingType spacing;
  MaskVolume::PointType origin;
  MaskVolume::DirectionType direction;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    size[axis] = grid.size[axis];
    spacing[axis] = grid.spacing[axis];
    origin[axis] = grid.origin[axis];
    for (unsigned int column = 0; column < 3; ++column)
      direction[axis][column] = grid.direction(axis, column);
  }
  mask->SetRegions(size);
  mask->SetSpacing(spacing);
  mask->SetOrigin(origin);
  mask->SetDirection(direction);
  mask->Allocate();

  unsigned char* voxel = mask->GetBufferPointer();
  for (std::size_t k = 0; k < grid.size[2]; ++k)
    for (std::size_t j = 0; j < grid.size[1]; ++j)
      for (std::size_t i = 0; i < grid.size[0]; ++i)
        *voxel++ = phantom.signedDistance(grid.physicalPoint(i, j, k)) <= 0.0 ? 1 : 0;
  return mask;
}

double distanceToSurface(const Phantom& phantom, const Point3& physical)
{
  return std::abs(phantom.signedDistance(Vector3(physical.x, physical.y, physical.z)));
}

VertexDistances vertexDistances(const Phantom& phantom, const TriangleMesh& mesh)
{
  VertexDistances distances;
  double sum = 0.0;
  for (const Point3& p : mesh.points)
  {
    const double d = distanceToSurface(phantom, p);
    sum += d;
    distances.max = std::max(distances.max, d);
  }
  distances.mean = mesh.points.empty() ? 0.0 : sum / static_cast<double>(mesh.points.size());
  return distances;
}

double meanSurfaceDistance(const Phantom& phantom, const TriangleMesh& mesh)
{
  double weighted = 0.0, area = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const Point3 n = areaNormal(a, b, c);
    const double triangleArea = 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const Point3 centroid{ (a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0, (a.z + b.z + c.z) / 3.0 };
    weighted += triangleArea * distanceToSurface(phantom, centroid);
    area += triangleArea;
  }
  return area > 0.0 ? weighted / area : 0.0;
}

} // namespace slicemesh

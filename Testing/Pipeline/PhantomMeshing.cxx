#include "PhantomMeshing.h"

#include "ContourExtraction.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace slicemesh::testing
{

PhantomMeshResult meshPhantom(const Phantom& phantom, const std::array<double, 3>& spacing, const Matrix3& direction,
                              const ReconstructionOptions& options, const UndersamplingOptions& undersampling)
{
  const GridSpec grid = gridAround(phantom, spacing, 2, direction);
  MaskVolume::Pointer mask = rasterizePhantom(phantom, grid);
  PhantomMeshResult result;
  std::size_t inside = 0;
  for (auto it = mask->GetBufferPointer(), end = it + mask->GetBufferedRegion().GetNumberOfPixels(); it != end; ++it)
    inside += *it != 0;
  result.voxelVolume = inside * spacing[0] * spacing[1] * spacing[2];

  // The CLI's order: contours -> intermediate sections (only where the options ask) -> reconstruction.
  const ContourStack stack = insertIntermediateSections(extractContours(mask), undersampling, &result.sections);
  const TriangleMesh stackMesh = reconstructSurface(stack, options, &result.statistics);
  result.mesh = mapToPhysicalSpace(stackMesh, sliceFrameOf(mask), CoordinateSystem::LPS);
  result.validation = validateMesh(result.mesh);

  result.lower = result.upper = result.mesh.points.front();
  for (const Point3& p : result.mesh.points)
  {
    const double d = distanceToSurface(phantom, p);
    result.meanDistance += d;
    result.maxDistance = std::max(result.maxDistance, d);
    result.lower = { std::min(result.lower.x, p.x), std::min(result.lower.y, p.y), std::min(result.lower.z, p.z) };
    result.upper = { std::max(result.upper.x, p.x), std::max(result.upper.y, p.y), std::max(result.upper.z, p.z) };
  }
  result.meanDistance /= static_cast<double>(result.mesh.points.size());
  return result;
}

Matrix3 rotation(const Vector3& axis, double angle)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

} // namespace slicemesh::testing

#include "PhantomMeshing.h"

#include "MaskMeshing.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace slicemesh::testing
{

PhantomMeshResult meshPhantom(const Phantom& phantom, const std::array<double, 3>& spacing, const Matrix3& direction,
                              const ReconstructionOptions& options, const UndersamplingOptions& undersampling,
                              SurfaceFinish finish)
{
  const GridSpec grid = gridAround(phantom, spacing, 2, direction);
  MaskVolume::Pointer mask = rasterizePhantom(phantom, grid);
  PhantomMeshResult result;
  std::size_t inside = 0;
  for (auto it = mask->GetBufferPointer(), end = it + mask->GetBufferedRegion().GetNumberOfPixels(); it != end; ++it)
    inside += *it != 0;
  result.voxelVolume = inside * spacing[0] * spacing[1] * spacing[2];

  // The one meshing path, as the CLI runs it (meshMask), with these options.
  MeshingOptions meshing;
  meshing.reconstruction = options;
  meshing.undersampling = undersampling;
  meshing.finishing.finish = finish;
  MeshedMask meshed = meshMask(mask, meshing);
  result.sections = meshed.meshing.sections;
  result.statistics = meshed.meshing.reconstruction;
  result.finish = meshed.meshing.surface.finish;
  result.fallback = meshed.meshing.surface.fallback;
  result.mesh = std::move(meshed.physical);
  result.validation = validateMesh(result.mesh); // in physical space: the mapping kept it valid and outward

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
  double area = 0.0;
  for (const Triangle& t : result.mesh.triangles)
  {
    const Point3 &a = result.mesh.points[t[0]], &b = result.mesh.points[t[1]], &c = result.mesh.points[t[2]];
    const Vector3 u(b.x - a.x, b.y - a.y, b.z - a.z), v(c.x - a.x, c.y - a.y, c.z - a.z);
    const double triangleArea = 0.5 * u.cross(v).norm();
    auto mid = [](const Point3& p, const Point3& q, double w) {
      return Point3{ p.x + w * (q.x - p.x), p.y + w * (q.y - p.y), p.z + w * (q.z - p.z) };
    };
    const Point3 centroid{ (a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0, (a.z + b.z + c.z) / 3.0 };
    const double d = (distanceToSurface(phantom, centroid) + distanceToSurface(phantom, mid(a, b, 0.5)) +
                      distanceToSurface(phantom, mid(b, c, 0.5)) + distanceToSurface(phantom, mid(c, a, 0.5))) /
                     4.0;
    result.surfaceDistance += triangleArea * d;
    area += triangleArea;
  }
  result.surfaceDistance /= area;
  return result;
}

Matrix3 rotation(const Vector3& axis, double angle)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

std::vector<PhantomTestGrid> phantomTestGrids()
{
  Matrix3 mirrored = Matrix3::Identity();
  mirrored(0, 0) = -1.0;
  return { { "iso1mm", { 1.0, 1.0, 1.0 }, Matrix3::Identity() },
           { "aniso08x08x3", { 0.8, 0.8, 3.0 }, Matrix3::Identity() },
           { "oblique", { 0.9, 1.1, 2.0 }, rotation({ 1.0, 2.0, 0.5 }, 0.6) },
           { "mirrored", { 1.0, 0.7, 1.5 }, mirrored * rotation({ 0.0, 0.0, 1.0 }, 0.3) } };
}

} // namespace slicemesh::testing

// Sampling a phantom on an image grid: the grid around a shape, its rasterized mask, and the
// distance of a physical point to the shape's surface (for measuring a mesh against the truth).
#ifndef PhantomGrid_h
#define PhantomGrid_h

#include "Phantom.h"
#include "Core/SliceMeshTypes.h"
#include "VolumeReader.h"

#include <array>

namespace slicemesh
{

/** An image grid: physical(i, j, k) = origin + direction * (i * spacing[0], j * spacing[1], k * spacing[2]). */
struct GridSpec
{
  std::array<std::size_t, 3> size{ 1, 1, 1 };
  std::array<double, 3>      spacing{ 1.0, 1.0, 1.0 };
  std::array<double, 3>      origin{ 0.0, 0.0, 0.0 };
  /** Columns are the grid's axis unit vectors in physical space (orthonormal, determinant +-1). */
  Matrix3 direction = Matrix3::Identity();

  Vector3 physicalPoint(std::size_t i, std::size_t j, std::size_t k) const;
};

/** A grid with the given spacing and axis directions that covers the shape's bounds plus
 *  marginVoxels empty voxels on every side. */
GridSpec gridAround(const Phantom& phantom, const std::array<double, 3>& spacing, int marginVoxels = 2,
                    const Matrix3& direction = Matrix3::Identity());

/** A mask on the grid: a voxel is inside (1) iff the phantom's signed distance at its centre is <= 0. */
MaskVolume::Pointer rasterizePhantom(const Phantom& phantom, const GridSpec& grid);

/** |signed distance|: how far a physical point is from the phantom's surface (mm). */
double distanceToSurface(const Phantom& phantom, const Point3& physical);

/** The mean and largest distanceToSurface over a mesh's vertices (0 for a mesh without any). */
struct VertexDistances
{
  double mean = 0.0;
  double max = 0.0;
};
VertexDistances vertexDistances(const Phantom& phantom, const TriangleMesh& mesh);

/** The mean distanceToSurface over a mesh's surface, not only its vertices: at each triangle's
 *  centroid, weighted by its area (0 for a mesh without area). A surface whose vertices lie on the
 *  truth can still cut the corners between them. */
double meanSurfaceDistance(const Phantom& phantom, const TriangleMesh& mesh);

} // namespace slicemesh

#endif

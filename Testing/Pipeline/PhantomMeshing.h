// Meshes an analytic phantom through the whole image path (rasterize, contours, reconstruction,
// physical space) and measures the result against the phantom's exact surface.
#ifndef PhantomMeshing_h
#define PhantomMeshing_h

#include "Sections/IntermediateSections.h"
#include "Measures/MeshValidation.h"
#include "MeshWriter.h"
#include "Phantom.h"
#include "PhantomGrid.h"
#include "Finishing/SurfaceFinishing.h"
#include "Tiling/SurfaceReconstruction.h"

namespace slicemesh::testing
{

struct PhantomMeshResult
{
  TriangleMesh mesh;               ///< physical (LPS) millimetres
  MeshValidation validation;
  SurfaceFinish finish = SurfaceFinish::Tiled; ///< what the finishing stage applied
  std::string fallback;            ///< why the finishing applied less than asked
  ReconstructionStatistics statistics;
  SectionStatistics sections;      ///< of the undersampling pre-stage (nothing inserted when it is off)
  double meanDistance = 0.0;       ///< mean over vertices of the distance to the exact surface (mm)
  double maxDistance = 0.0;
  /** Area-weighted mean distance of the surface (each triangle sampled at its centroid and edge
   *  midpoints): what the triangles' interiors do, which the vertices alone do not show (mm). */
  double surfaceDistance = 0.0;
  double voxelVolume = 0.0;        ///< volume of the rasterized mask (mm^3)
  Point3 lower, upper;             ///< the mesh's bounding box
};

/** The phantom rasterized and meshed through the one meshing path (meshMask) with the contours as
 *  traced, these tiling and correspondence options, and `finish` at the grid's automatic values (as
 *  the CLI runs it by default with Remeshed; Tiled measures the tiling itself). */
PhantomMeshResult meshPhantom(const Phantom& phantom, const std::array<double, 3>& spacing,
                              const Matrix3& direction = Matrix3::Identity(),
                              const ReconstructionOptions& options = {},
                              const UndersamplingOptions& undersampling = {},
                              SurfaceFinish finish = SurfaceFinish::Tiled);

/** A rotation by angle (radians) about a unit axis. */
Matrix3 rotation(const Vector3& axis, double angle);

/** A grid the phantoms are rasterized on: voxel spacing (mm) and direction matrix. */
struct PhantomTestGrid
{
  const char* name;
  std::array<double, 3> spacing;
  Matrix3 direction = Matrix3::Identity();
};

/** The four grids the end-to-end phantom tests run on: isotropic 1 mm, 0.8 x 0.8 x 3 mm, an oblique
 *  anisotropic one and a mirrored rotated one (negative determinant). */
std::vector<PhantomTestGrid> phantomTestGrids();

} // namespace slicemesh::testing

#endif

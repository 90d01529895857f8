// Meshes an analytic phantom through the whole image path (rasterize, contours, reconstruction,
// physical space) and measures the result against the phantom's exact surface.
#ifndef PhantomMeshing_h
#define PhantomMeshing_h

#include "IntermediateSections.h"
#include "MeshValidation.h"
#include "MeshWriter.h"
#include "Phantom.h"
#include "PhantomGrid.h"
#include "SurfaceFinishing.h"
#include "SurfaceReconstruction.h"

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

/** `finish`: the finishing stage after the tiling (SurfaceFinishing.h) at the automatic edge length
 *  of the grid, as the CLI runs it by default with Remeshed; Tiled measures the tiling itself. */
PhantomMeshResult meshPhantom(const Phantom& phantom, const std::array<double, 3>& spacing,
                              const Matrix3& direction = Matrix3::Identity(),
                              const ReconstructionOptions& options = {},
                              const UndersamplingOptions& undersampling = {},
                              SurfaceFinish finish = SurfaceFinish::Tiled);

/** A rotation by angle (radians) about a unit axis. */
Matrix3 rotation(const Vector3& axis, double angle);

} // namespace slicemesh::testing

#endif

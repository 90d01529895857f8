// The meshing path of the method (Documentation/Algorithm.md): the traced contours of one structure
// in; prepared, bridged, tiled, checked, finished and measured surface out. Every way into SliceMesh
// (a mask, a label of a label map, an ROI of a structure set) meshes through this one path.
#ifndef MeshContours_h
#define MeshContours_h

#include "Measures/DirichletEnergy.h"
#include "Measures/MeshQuality.h"
#include "Meshing/MeshingOptions.h"

#include <array>
#include <functional>

namespace slicemesh
{

/** The stages of the path, in order. Each needs only the structure's own earlier stages, so
 *  structures can be taken stage by stage side by side (a multi-label run reports each stage once). */
enum class MeshingStage
{
  Preparation,    ///< contours smoothed or kept as traced, simplified, resampled (step 1)
  Correspondence, ///< distance-rule bridging and sections in undersampled slabs (step 2)
  Tiling,         ///< the paper's tiling with its Steiner points (steps 3-8)
  Validation,     ///< the tiling checked: closed, manifold, oriented, no self-intersections
  Finishing       ///< remeshed and smoothed in 3D where it stays valid (step 9), then measured
};

/** "Preparation", "Correspondence", "Tiling", "Validation", "Finishing". */
const char* meshingStageName(MeshingStage stage);

struct MeshMeasures
{
  MeshQuality shape;         ///< of the finished mesh
  DirichletEnergy dirichlet; ///< of the tiling: the paper's optimality is the tiling's
  long genus = -1;           ///< of the finished mesh; -1 when undefined
  double pointSpacing = 0.0; ///< mean in-plane distance between the tiled contours' points (mm)
  double sliceSpacing = 0.0; ///< mm
};

/** One structure on its way through the path; each stage fills its part. */
struct MeshedContours
{
  MeshingOptions options; ///< resolved for the grid (resolvedMeshingOptions)
  /** The contours: as traced, then prepared (Preparation), then with their sections (Correspondence):
   *  what was tiled. */
  ContourStack stack;
  SectionStatistics sections;
  ReconstructionStatistics reconstruction;
  /** The volume the finished surface encloses (mm^3), as voxels count it: the mask's voxels, or
   *  the traced contours' prismVolume; 0 (caps at the slice) keeps the tiling's, as do slabs given
   *  intermediate sections (their shape between the slices is the implicit function's). */
  double targetVolume = 0.0;
  /** Each traced contour's share of targetVolume and a point of it (contourVolumes: for a mask, its
   *  own pixels), by which every connected piece of the surface gets the volume of its own contours. */
  std::vector<ContourVolume> targetShares;
  TriangleMesh tiling;             ///< stack frame, mm
  /** The tiling's validation; its self-intersection test is run only when the tiling is the
   *  surface asked for (finish Tiled); finishSurface checks what of a finished tiling it keeps. */
  MeshValidation tilingValidation;
  FinishedSurface surface;         ///< the finished mesh, its validation and what was applied
  MeshMeasures measures;
};

/** A structure's traced contours (stack frame, mm) on a grid of this spacing (x, y, slice; mm), at
 *  the start of the path, its options resolved. `volume` is the structure's volume as voxels count it
 *  (mm^3); 0: the traced contours' prismVolume. */
MeshedContours startMeshing(ContourStack traced, const MeshingOptions& options, const std::array<double, 3>& spacing,
                            double volume = 0.0);

/** Runs one stage on a structure whose earlier stages have run. `fraction` (may be empty) hears the
 *  share of the stage done, 0..1. Throws Error on contours it cannot mesh (no triangles from the
 *  tiling included). */
void runMeshingStage(MeshingStage stage, MeshedContours& meshing, const std::function<void(double)>& fraction = {});

/** Every stage in order on a structure at the start of the path. `progress` (may be empty) hears the
 *  stage and the share of it done. */
void runMeshingStages(MeshedContours& meshing, const std::function<void(MeshingStage, double)>& progress = {});

/** startMeshing, then every stage in order. `progress` (may be empty) hears the stage and the share
 *  of it done. */
MeshedContours meshContours(const ContourStack& traced, const MeshingOptions& options,
                            const std::array<double, 3>& spacing,
                            const std::function<void(MeshingStage, double)>& progress = {});

} // namespace slicemesh

#endif

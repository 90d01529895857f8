// What a run measured about its mesh: the one-line summary and the --report JSON file. Only
// formatting: the measures are Logic's (MeshValidation, MeshQuality, DirichletEnergy).
#ifndef QualityReport_h
#define QualityReport_h

#include "Measures/DirichletEnergy.h"
#include "Measures/MeshQuality.h"
#include "Measures/MeshValidation.h"
#include "Core/MeasureText.h"
#include "Core/SliceMeshTypes.h"

#include <chrono>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace slicemesh::cli
{

/** Wall-clock time per stage, in the order the stages started. */
class StageTimes
{
public:
  void start(const std::string& stage);
  std::vector<std::pair<std::string, double>> seconds() const;

private:
  using Clock = std::chrono::steady_clock;
  std::vector<std::pair<std::string, Clock::time_point>> m_Starts;
};

struct RunQuality
{
  MeshQuality shape;         ///< of the mesh as written: the finished surface
  DirichletEnergy dirichlet; ///< of the tiling, before finishing (the paper's optimality is the tiling's)
  long genus = -1;
  std::string requestedFinish;   ///< "Remeshed", "Smoothed" or "Tiled" (finishName), as asked
  std::string finish;            ///< as applied: less than asked after a fallback; "Mixed" over labels that differ
  double targetEdgeLength = 0.0; ///< of the remeshing (mm), when Remeshed was asked; else 0
  int smoothingIterations = 0;   ///< Taubin pairs, when Remeshed or Smoothed was asked; else 0
  double smoothingPassBand = 0.0;
  std::array<double, 3> smoothingMaxDisplacement{}; ///< mm along the image axes; 0: unbounded
  int smoothingFeaturePairs = 0; ///< pairs after which sharp features are held (SurfaceSmoothingOptions)
  std::array<double, 3> smoothingMaxDisplacementAwayFromFeatures{}; ///< mm, the bound after those pairs
  std::string fallback;          ///< why less was applied than asked (SurfaceFinishing.h); empty when all of it was
  std::size_t smallPiecesRemeshed = 0; ///< specks remeshed at their own scale (FinishedSurface::smallPiecesRemeshed)
  std::size_t smallPiecesAsTiled = 0; ///< specks left as tiled (FinishedSurface::smallPiecesAsTiled)
  std::size_t unsmoothedVertices = 0; ///< where smoothing made triangles cross, or a piece crossed another (FinishedSurface)
  /** Of remeshed pieces, kept as tiled where their remesh crossed itself or another piece. */
  std::size_t trianglesKeptTiled = 0;
  /** The volume the finished surface was given (mm^3): its voxels', or its contours' areas times
   *  the slice spacing; 0 where it keeps the tiling's (caps at the slice, intermediate sections). */
  double targetVolume = 0.0;
  /** Flips, collapses and vertex moves that undid a remesh's few crossings without a second remesh
   *  (FinishedSurface::crossingRepairOperations). */
  std::size_t crossingRepairOperations = 0;
  /** Flips and collapses that took narrow triangles away from finished pieces
   *  (FinishedSurface::narrowTrianglesWidened). */
  std::size_t narrowTrianglesWidened = 0;
  /** Connected pieces remeshed, smoothed only and left as tiled (FinishedSurface::piecesByFinish,
   *  indexed by SurfaceFinish); summed over labels. */
  std::array<std::size_t, 3> piecesByFinish{};
  /** The automatic values as resolved for this mesh (MeshingOptions, ReconstructionStatistics). */
  std::string contourPreparation;      ///< "Traced" or "Smoothed"
  double contourPointSpacing = 0.0;    ///< resampling spacing (mm); 0: the traced points kept
  double contourSmoothingMaxShift = 0.0; ///< mm, when Smoothed
  double contourSimplification = 0.0;  ///< Douglas-Peucker tolerance (mm); 0: none
  double wallRowHeight = 0.0;          ///< mm
  /** Where the end caps lie, which is how the volume counts the end slices: "HalfSliceBeyond"
   *  (half a slice beyond the last contour, as planning systems count) or "AtSlice". */
  std::string capPlacement;
  double steinerSpacing = 0.0;         ///< mm
  double pointSpacing = 0.0;       ///< mean in-plane distance between contour points (mm)
  double sliceSpacing = 0.0;       ///< mm
  std::vector<std::pair<std::string, double>> stageSeconds;
};


/** The finishing part of the summary: "finish Remeshed (target edge 1.14 mm)"; when some pieces got
 *  less than asked, "finish Remeshed (target edge 1.14 mm; 3 of 2149 pieces 2 smoothed only, 1 left
 *  as tiled, see the warning; 40 specks kept as tiled)"; when none got what was asked, "finish
 *  Tiled (Remeshed asked; see the warning)". */
std::string finishSummary(const RunQuality& quality);

/** "finish Remeshed (target edge 1.10 mm), 41649 vertices, 1 component, manifold, no
 *  self-intersections, genus 0, min angle 21.3 deg, <30 deg 0.4%, <10 deg 0.0%, aspect ratio mean
 *  1.18 max 2.71, area 9126.4 mm^2, point/slice spacing 0.83, Dirichlet energy of the tiling 812.3
 *  mm^2; stages Reading 0.01 s, ...". `eachStructure`: the validation sums structures checked each
 *  on its own (labels or ROIs of one run, which may touch or cross each other): "no
 *  self-intersections within a structure". */
std::string qualitySummary(const MeshValidation& validation, const RunQuality& quality, bool eachStructure = false);

/** The figures of one label of a multi-label run (runPipeline), as the report lists it. */
struct LabelReport
{
  int label = 0;
  std::string name;
  std::string path;             ///< the per-label file, empty when no folder was given
  MeshValidation validation;    ///< of the label's mesh
  RunQuality quality;           ///< of the label's mesh (no stage times: seconds below)
  std::size_t voxels = 0;
  std::size_t contourPoints = 0;     ///< of the label's contours
  std::size_t removedComponents = 0; ///< components under --minimumComponentVolume, dropped
  bool dropped = false;         ///< nothing to mesh, which is no failure (droppedBecause says why)
  std::string droppedBecause;   ///< an empty segment, every component under --minimumComponentVolume, no closed contour
  double seconds = 0.0;
  std::string error;            ///< why the label failed; empty on success
  bool meshed() const { return error.empty() && !dropped; }
};

/** Combines the labels' figures into one for the whole run (their meshes taken together): shape
 *  measured on `allTriangles` (the merged mesh; angles do not change from stack frame to physical
 *  space), Dirichlet energies and counts summed (largest decreases: the largest), genus from the
 *  summed validation, spacings averaged over the labels weighted by their contour points. The
 *  finish is the labels' when they agree, else "Mixed"; the fallbacks are joined, each after its
 *  label. */
RunQuality combinedQuality(const std::vector<LabelReport>& labels, const MeshValidation& summed,
                           const TriangleMesh& allTriangles);

/** `text` as a JSON string, quoted and escaped. Always valid UTF-8, as JSON must be: a byte that
 *  starts no valid UTF-8 sequence (a name in another encoding) becomes U+FFFD. */
std::string jsonString(const std::string& text);

/** Writes the report as JSON (atomically: a temporary name, renamed when complete); with labels,
 *  a "labels" array follows, one entry per label with its own mesh, quality and Dirichlet blocks.
 *  Each "mesh" block says what its validation covers: "validatedAs": "wholeMesh" (one mesh, or one
 *  label's), or at the top of a per-label run "eachStructure" with a "validationNote": the figures
 *  sum the labels', each checked on its own, and different labels' meshes may touch or intersect.
 *  Throws slicemesh::Error when it cannot. */
void writeQualityReport(const std::string& path, const std::string& inputVolume, const std::string& outputModel,
                        const MeshValidation& validation, const RunQuality& quality, double seconds,
                        const std::vector<LabelReport>& labels = {});

} // namespace slicemesh::cli

#endif

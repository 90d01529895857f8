// Non-shrinking smoothing of a closed triangle mesh (Taubin's lambda/mu filter on the umbrella
// operator): takes the voxel staircase out of a surface traced from a mask, in 3D.
#ifndef SurfaceSmoothing_h
#define SurfaceSmoothing_h

#include "Core/SliceMeshTypes.h"

#include <array>
#include <vector>

namespace slicemesh
{

struct SurfaceSmoothingOptions
{
  /** Number of lambda/mu step pairs; 0 leaves the mesh as it is. Sharp features get the first
   *  featurePairs of them only. */
  int iterations = 200;
  /** Pairs the whole surface gets, within maxDisplacement. Then the sharp features are found (a
   *  vertex one of whose triangles turns from its normal by more than featureAngle, and the vertices
   *  within two rings of it) and held where they are, while the rest of the surface gets the other
   *  pairs within maxDisplacementAwayFromFeatures. On a gently curved surface the
   *  staircase's terraces are many edges long (a sphere's flanks, where a slice or a pixel row runs
   *  along the surface), farther than 100 pairs reach, and the true surface lies anywhere within
   *  half a voxel of a terrace; the same pairs on a sharp edge (a box's, a plate's rim) would only
   *  round it further. */
  int featurePairs = 50;
  /** Degrees; about a radius of curvature of three edges: a sphere of 20 voxels' radius turns by
   *  about 2 degrees per edge, a box's edge by 45. */
  double featureAngle = 10.0;
  /** The bound away from sharp features after featurePairs (mm along x, y and z; where smaller than
   *  maxDisplacement, as all 0 are, maxDisplacement). */
  std::array<double, 3> maxDisplacementAwayFromFeatures{ 0.0, 0.0, 0.0 };
  /** Taubin's pass band k_PB = 1/lambda + 1/mu: mesh frequencies below it (the shape) pass, the
   *  staircase of a mask (periods of a few edges) is damped. lambda is 0.63; mu follows from k_PB. */
  double passBand = 0.01;
  /** No vertex ends outside the ellipsoid of these semi-axes around where it started (mm, along the
   *  mesh's x, y and z: for a stack, the image's voxel axes; all 0: unbounded), checked after every
   *  step pair; a vertex that has left it goes to its nearest point (EllipsoidClamp.h). The staircase of a mask is a fraction of a voxel deep along each axis, so a bound of
   *  that fraction of each voxel side takes it out but keeps the filter from rounding a sharp edge
   *  over more than that. */
  std::array<double, 3> maxDisplacement{ 0.0, 0.0, 0.0 };
  /** Steps of tangential relaxation after the filter (each vertex half way to its neighbours' mean,
   *  within its tangent plane, within the same bound): the filter crowds vertices where the surface
   *  folds sharply, and its triangles there get small angles. The shape moves only to second order. */
  int tangentialRelaxations = 3;
  /** Further steps of the same relaxation for the vertices of the triangles that still have an angle
   *  under 30 degrees and their neighbours only: where a thin structure folds sharply (a tract a
   *  voxel thick) a few steps do not undo the crowding, and more over the whole surface would move
   *  it everywhere. */
  int narrowTriangleRelaxations = 30;
};

/** The pairs the whole surface gets before sharp features are held: featurePairs, within 0 and
 *  iterations. */
int pairsBeforeFeaturesHeld(const SurfaceSmoothingOptions& options);

/** The bound away from sharp features as applied: along each axis the larger of maxDisplacement and
 *  maxDisplacementAwayFromFeatures. */
std::array<double, 3> boundAwayFromFeatures(const SurfaceSmoothingOptions& options);

/** Smooths every vertex of the mesh: `iterations` pairs of p += lambda * L(p) and p += mu * L(p),
 *  where L(p) is the mean of p's neighbours minus p, each pair followed by the maxDisplacement
 *  clamp (after featurePairs, sharp features held and the clamp widened elsewhere),
 *  `tangentialRelaxations` steps along the surface (within the same clamp) and
 *  `narrowTriangleRelaxations` more for the vertices of narrow triangles only; then gives
 *  every connected component its signed
 *  volume back by one offset along the vertex normals (small structures, a few edges across, shrink
 *  under the filter). A component that lost half its volume or more (a speck the filter collapses)
 *  keeps its unsmoothed vertices instead. The connectivity is not changed. The vertices are moved on
 *  `threads` threads (0: every core), each from the previous step's positions, so the result does
 *  not depend on the number. The vertices flagged in `held` (one flag per vertex; empty: none) take
 *  each step pair and are put back after it, as sharp features are, and neither the relaxation nor
 *  the volume offset moves them: a drawn contour's vertices stay on it. `unsmoothed`, when given,
 *  receives the points as they were before (from the smoothing's own copy: a caller that keeps
 *  them needs no copy of its own held through the smoothing). Should it throw (out of memory), the
 *  mesh may be left without its points: the smoothing works on its own copies of them.
 *  G. Taubin, "A signal processing approach to fair surface design", SIGGRAPH 1995. */
void smoothSurface(TriangleMesh& mesh, const SurfaceSmoothingOptions& options, unsigned int threads = 1,
                   const std::vector<char>& held = {}, std::vector<Point3>* unsmoothed = nullptr);

/** Only the relaxation around narrow triangles of smoothSurface (options.narrowTriangleRelaxations
 *  steps, options.maxDisplacement around `start`, one point per vertex), with the vertices flagged
 *  in `fixed` kept where they are: for a smoothed surface some of whose vertices were put back where
 *  they were before the smoothing. Returns whether any vertex was relaxed (false: mesh untouched).
 *  The same points on any number of threads. */
bool relaxNarrowTriangles(TriangleMesh& mesh, const std::vector<Point3>& start, const std::vector<char>& fixed,
                          const SurfaceSmoothingOptions& options, unsigned int threads = 1);

/** Moves every vertex of a closed, consistently oriented mesh along its vertex normal by one common
 *  distance so that its signed volume becomes `volume` (a few Newton steps: the volume grows by the
 *  area per unit of offset). For one connected piece; offsets large against the mesh's features fold
 *  it. The vertices flagged in `held` (empty: none) stay; the others move by the distance that gives
 *  the volume with them held, but no farther than `maxOffset` (mm; 0: unbounded): where few vertices
 *  are free the volume is then not reached. On `threads` threads, with the same result on any number. */
void offsetToVolume(TriangleMesh& mesh, double volume, const std::vector<char>& held = {}, double maxOffset = 0.0,
                    unsigned int threads = 1);

} // namespace slicemesh

#endif

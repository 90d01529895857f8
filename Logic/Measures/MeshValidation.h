// Checks that a triangle mesh is a valid closed surface, and measures it.
#ifndef MeshValidation_h
#define MeshValidation_h

#include "Core/SliceMeshTypes.h"

#include <string>
#include <utility>
#include <vector>

namespace slicemesh
{

struct MeshValidation
{
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerateTriangles = 0;        ///< zero area or repeated vertex
  std::size_t boundaryEdges = 0;              ///< edges with one triangle
  std::size_t nonManifoldEdges = 0;           ///< edges with more than two triangles
  std::size_t nonManifoldVertices = 0;        ///< vertices whose triangles form more than one fan
  std::size_t inconsistentEdges = 0;          ///< edges used twice in the same direction
  /** Components facing against their nesting: an outer surface facing in, or a cavity's wall facing
   *  out (measured on closed, manifold, consistently wound meshes; else 0). */
  std::size_t misorientedComponents = 0;
  std::size_t foldedEdges = 0;                ///< edges whose two triangles fold onto each other (dihedral angle under 1 degree)
  std::size_t selfIntersections = 0;          ///< pairs of triangles that intersect other than along shared simplices
  bool selfIntersectionChecked = false;       ///< false when the mesh was not manifold enough to check
  std::size_t components = 0;
  long eulerCharacteristic = 0;               ///< V - E + F
  double area = 0.0;                          ///< mm^2
  double volume = 0.0;                        ///< signed enclosed volume, mm^3 (positive when outward)
  double minAngleDegrees = 0.0;
  double fractionAnglesBelow30 = 0.0;         ///< fraction of triangles with an angle under 30 degrees

  bool closed() const { return boundaryEdges == 0; }
  bool manifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
  bool oriented() const { return inconsistentEdges == 0 && misorientedComponents == 0 && volume > 0.0; }
  /** Closed, manifold, oriented, without degenerate triangles: valid but for what the self-intersection
   *  test says (or would say, when it was not run). */
  bool soundTopology() const { return closed() && manifold() && oriented() && degenerateTriangles == 0; }
  bool valid() const { return soundTopology() && selfIntersectionChecked && selfIntersections == 0; }
  /** One line such as "12840 triangles, closed, manifold, no self-intersections, volume 33400.1 mm^3". */
  std::string summary() const;
};

/** Measures the mesh and checks it: boundary and non-manifold edges, non-manifold vertices,
 *  consistent orientation, degenerate triangles and self-intersections (CGAL). Folds (two triangles
 *  on one edge lying almost on top of each other) are counted but do not make a mesh invalid: no
 *  triangles cross there, but a rotation or rounding of the coordinates may make them cross. */
MeshValidation validateMesh(const TriangleMesh& mesh);

/** validateMesh, with the pairs of triangles that cross (as selfIntersectingPairs gives them) from
 *  the same test: for a caller that acts on them, one test of the whole mesh instead of two. Empty
 *  when the test was not run (a mesh not manifold). */
MeshValidation validateMesh(const TriangleMesh& mesh, std::vector<std::pair<std::size_t, std::size_t>>& crossings);

/** validateMesh(mesh, crossings) for a mesh whose vertices flagged in `moved` have moved since its
 *  last validation (`crossings` holds that validation's pairs and is replaced by the new ones): only
 *  the triangles that moved are tested for crossings (selfIntersectingTrianglePairsAfterMoving).
 *  `checkedBefore`: whether that validation ran the self-intersection test; if not, the whole test. */
MeshValidation validateMeshAfterMoving(const TriangleMesh& mesh, bool checkedBefore, const std::vector<char>& moved,
                                       std::vector<std::pair<std::size_t, std::size_t>>& crossings);

/** validateMeshAfterMoving for a mesh whose triangles are those `before` validated, the same in the
 *  same order (only their count is checked), and whose points flagged in `moved` alone have moved
 *  since (`crossings`: that validation's pairs, replaced by the new ones). What the triangles alone decide (closed, manifold, wound, components, Euler
 *  characteristic) is `before`'s; the rest is measured again, folds only around the moved points.
 *  The same result as validateMesh; the edges are not gathered again, which was most of a put-back
 *  piece's validation. A `before` not closed, manifold and wound alike, or with folds, is validated
 *  as validateMeshAfterMoving does. */
MeshValidation validateMeshAfterMovingPoints(const TriangleMesh& mesh, const MeshValidation& before,
                                             const std::vector<char>& moved,
                                             std::vector<std::pair<std::size_t, std::size_t>>& crossings);

/** validateMesh of `mesh` after a local change (flips, collapses, moved points; vertices gone and the
 *  rest renumbered allowed) since `before`, whose self-intersection test found no crossing among the
 *  triangles the change left as they were: `before.selfIntersections` counts only those (0; a repair
 *  that undid every crossing by changing a triangle of each passes its validation with 0 there).
 *  `changed`: a flag per vertex of `mesh`, set on every corner still in the mesh of each triangle
 *  added or removed since, and on every corner of each triangle with a corner that moved. Elsewhere
 *  the triangles are as they were: only the triangles with a changed corner are tested for
 *  crossings, and where `before` was closed, manifold, consistently wound and without folds, only
 *  the edges and fans at changed vertices are gathered again (else all); what the points decide and
 *  the components are measured again whole. The same result as validateMesh, which a `before`
 *  without that test gets (`crossings`: the new pairs, as validateMesh gives them). */
MeshValidation validateMeshAfterLocalChange(const TriangleMesh& mesh, const MeshValidation& before,
                                            const std::vector<char>& changed,
                                            std::vector<std::pair<std::size_t, std::size_t>>& crossings);

/** validateMesh without the self-intersection test (selfIntersectionChecked false): the topology,
 *  orientation and measures, in time linear in the triangles (and, for a mesh of several components
 *  whose boxes nest, O(n log n) to tell which component lies inside which). */
MeshValidation validateMeshTopology(const TriangleMesh& mesh);

/** The validation of meshes laid side by side in one mesh without shared vertices, from theirs:
 *  counts, area and volume summed (the misoriented components too: nesting between the meshes is
 *  the caller's to check, see ComponentOrientation.h), the smallest angle the smallest, the share of triangles under 30
 *  degrees weighted by triangles; `crossingPairs` pairs of triangles of different meshes that
 *  intersect are added to the self-intersections. */
MeshValidation joinedValidation(const std::vector<MeshValidation>& parts, std::size_t crossingPairs);

/** The signed volume the mesh encloses (mm^3): positive when its triangles wind counter-clockwise
 *  seen from outside; a closed surface's, whatever the origin. */
double signedVolume(const TriangleMesh& mesh);

/** The pairs of triangles (indices into mesh.triangles) that intersect other than along shared
 *  simplices, as validateMesh counts them (selfIntersectingTrianglePairs, on every core). */
std::vector<std::pair<std::size_t, std::size_t>> selfIntersectingPairs(const TriangleMesh& mesh);

} // namespace slicemesh

#endif

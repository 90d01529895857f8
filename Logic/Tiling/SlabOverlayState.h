// Internal to the tiling: the state of one slab shared by the files that tile it (SlabTiling.h's
// SlabOverlay::Impl). The overlay of the two slices in one constrained Delaunay triangulation
// (OverlayTriangulation.cxx), its faces' regions and difference polygons (RegionClassification.cxx),
// the heights of points inside the slab (SlabHeights.cxx), Steiner points (SteinerPlacement.cxx),
// flips towards 3D quality (SurfaceMetricFlips.cxx), and the triangles written out (SlabEmission.cxx).
#ifndef SlabOverlayState_h
#define SlabOverlayState_h

#include "Core/NearestSegment.h"
#include "Core/SpatialHash.h"
#include "Tiling/SlabTiling.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace slicemesh
{
namespace slab
{

// Which slice a lifted point belongs to.
enum Level : signed char
{
  NoLevel = -1,
  LowerLevel = 0,
  UpperLevel = 1
};

struct FaceData
{
  bool visited = false;
  bool inLower = false;
  bool inUpper = false;
  int lowerInnermost = -1; ///< innermost lower contour containing the face
  int upperInnermost = -1;
  int component = -1;      ///< difference polygon the face belongs to, -1 outside the symmetric difference
  std::array<signed char, 3> cornerLevel{ NoLevel, NoLevel, NoLevel }; ///< for corners on both slices
  std::array<std::int32_t, 3> lifted{ -1, -1, -1 };                   ///< mesh ids, in output winding
  std::array<std::int32_t, 3> cornerId{ -1, -1, -1 }; ///< chain node taken by a corner where the surface switches slices
  /** The lifted triangle's smallest angle, as the surface-metric flips last ranked their edges by it:
   *  valid while rankedIn is the Impl's flipRankings (a face's three edges ask for it in one ranking). */
  double rankedAngle = 0.0;
  std::uint32_t rankedIn = 0;
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase =
  CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<FaceData, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using VertexHandle = CDT::Vertex_handle;
using FaceHandle = CDT::Face_handle;

/** A point of the projected overlay: a vertex of the lower slice, of the upper slice, of both
 *  (the slices meet there), or a Steiner point inside a difference polygon. */
struct OverlayVertex
{
  Point2 p;
  std::int32_t lowerId = -1; ///< mesh id on the lower slice
  std::int32_t upperId = -1;
  std::int32_t steinerId = -1;
  bool onBoth() const { return lowerId >= 0 && upperId >= 0; }
  bool isSteiner() const { return steinerId >= 0; }
};

/** What an overlay edge is: part of a lower contour, an upper contour, or both. `from` is the
 *  endpoint the contour leaves from (its solid lies to the left). */
struct OverlayEdge
{
  bool lower = false;
  bool upper = false;
  int lowerFrom = -1;
  int upperFrom = -1;
  int lowerContour = -1;
  int upperContour = -1;
};

/** The key of the overlay edge between vertices a and b, either way round. */
inline std::uint64_t edgeKey(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/** A difference polygon: a connected piece of (lower \ upper) or (upper \ lower). */
struct Component
{
  bool lowerSide = false; ///< part of lower \ upper: the surface over it has the solid below
  bool touchesLowerLevel = false;
  bool touchesUpperLevel = false;
  bool isCap() const { return touchesLowerLevel != touchesUpperLevel; }
  Level capLevel() const { return touchesLowerLevel ? LowerLevel : UpperLevel; }
};

/** Faces around a vertex between two consecutive contour edges, in counter-clockwise order. */
struct Sector
{
  VertexHandle vertex;
  std::vector<FaceHandle> faces;
  std::vector<VertexHandle> fan; ///< far ends of the interior edges between consecutive faces
  Level startLevel = NoLevel;
  Level endLevel = NoLevel;
};

/** The finite edges, each once, in an order that depends only on the triangulation (never on memory
 *  addresses), so that flips and Steiner points, and so the mesh, are the same in every run. */
std::vector<CDT::Edge> finiteEdgesInStableOrder(const CDT& cdt);

/** The finite edges of the finite faces around `around`, each once, in the same kind of order. */
std::vector<CDT::Edge> finiteEdgesAround(const CDT& cdt, const std::vector<VertexHandle>& around);

/** The finite faces around `around`, each once, in an order that depends only on the triangulation. */
std::vector<FaceHandle> finiteFacesAround(const CDT& cdt, const std::vector<VertexHandle>& around);

} // namespace slab

struct SlabOverlay::Impl
{
  const PreparedSlice* lower = nullptr;
  const PreparedSlice* upper = nullptr;
  double z0 = 0.0;
  double z1 = 0.0;
  double tolerance = 0.0;

  std::vector<slab::OverlayVertex> vertices;
  std::unordered_map<std::uint64_t, slab::OverlayEdge> edges;
  slab::CDT cdt;
  std::vector<slab::Component> components;
  std::vector<char> lowerContinues, upperContinues;
  std::vector<std::pair<int, int>> correspondences;

  // Segments of each slice, for the distance interpolation of Steiner heights.
  std::vector<std::pair<Point2, Point2>> lowerSegments, upperSegments;
  std::unique_ptr<NearestSegment> lowerNearest, upperNearest;
  double typicalEdge = 1.0;
  std::uint32_t flipRankings = 0; ///< rankings of the surface-metric flips so far (FaceData::rankedIn)
  bool flipsSettled = true;       ///< no pass of the surface-metric flips stopped at its limit (never reset)

  // Height of the flat cap over each cap component, recomputed with the components.
  std::vector<double> capZ;
  const SlabLiftOptions* liftOptions = nullptr;

  // OverlayTriangulation.cxx: the two slices' points and contour edges in one CDT.
  void buildVertices();
  void buildEdges();
  void triangulate();
  const slab::OverlayEdge* edgeBetween(slab::VertexHandle a, slab::VertexHandle b) const
  {
    auto it = edges.find(slab::edgeKey(a->info(), b->info()));
    return it == edges.end() ? nullptr : &it->second;
  }
  /** Where p lies in the overlay (CGAL's locate). The walk starts at a vertex in p's cell of
   *  `vertexCells`, or else where the last one ended: a walk from CGAL's own start crosses the slab,
   *  which for a slab long and thin (a row of specks, a comb, nested rings) made the tiling's time
   *  grow with the square of its points. On an edge, of its two faces the one whose corner across the
   *  edge has the lower vertex id (the finite one, by an infinite face), so that the answer never
   *  depends on where the walk started. */
  slab::FaceHandle locate(const slab::Kernel::Point_2& p, slab::CDT::Locate_type& type, int& index) const;
  /** Adds an overlay vertex to `vertexCells` (its id is its info()). */
  void addToVertexCells(slab::VertexHandle v);
  /** The face a new point at p would go into; an infinite face where p is a vertex already or lies
   *  outside the overlay. */
  slab::FaceHandle faceFor(const Point2& p) const
  {
    slab::CDT::Locate_type type;
    int index = 0;
    const slab::FaceHandle f = locate(slab::Kernel::Point_2(p.x, p.y), type, index);
    return type == slab::CDT::VERTEX ? cdt.infinite_face() : f;
  }
  /** The overlay's vertices by cells a few typical edges wide, as ids into `vertexHandles`: where
   *  locate's walks start (vertices, not faces: insertions delete faces, and no vertex is removed). */
  std::unique_ptr<SpatialHash> vertexCells;
  std::vector<slab::VertexHandle> vertexHandles;
  mutable slab::VertexHandle locateHint; ///< where the last walk ended; null: CGAL's own start

  // RegionClassification.cxx: which regions each face lies in, the correspondences, the difference
  // polygons, and the sectors around vertices common to both slices.
  void classify();
  /** Every face's corner levels back to none, as classify() leaves them: what a Steiner insertion
   *  changes of the classification (its new faces inherit the rest, see insertSteiner). */
  void forgetCornerLevels();
  std::vector<slab::Sector> sectorsAround(slab::VertexHandle v);
  std::vector<slab::Sector> mixedSectors(bool assignCornerLevels);
  slab::Level edgeLevel(const slab::OverlayEdge& e, bool lowerSide) const
  {
    if (lowerSide)
      return e.lower ? slab::LowerLevel : slab::UpperLevel;
    return e.upper ? slab::UpperLevel : slab::LowerLevel;
  }
  bool isDifference(slab::FaceHandle f) const { return !cdt.is_infinite(f) && f->info().component >= 0; }
  bool inMixed(slab::FaceHandle f) const { return isDifference(f) && !components[f->info().component].isCap(); }
  bool isCapFace(slab::FaceHandle f) const { return isDifference(f) && components[f->info().component].isCap(); }
  slab::Level singleLevel(const slab::OverlayVertex& v) const
  {
    if (v.isSteiner() || v.onBoth())
      return slab::NoLevel;
    return v.lowerId >= 0 ? slab::LowerLevel : slab::UpperLevel;
  }

  // SlabHeights.cxx: the heights of points inside the slab and of the caps.
  double interpolatedHeight(const Point2& p) const;
  void computeCapHeights();
  double capLevelZ(int component) const { return components[component].capLevel() == slab::LowerLevel ? z0 : z1; }
  double domeHeight(int component, const Point2& p) const;
  double steinerHeight(slab::FaceHandle f, const Point2& p) const
  {
    return isCapFace(f) ? domeHeight(f->info().component, p) : interpolatedHeight(p);
  }
  /** Faces whose chords must not lie flat on a slice plane: mixed ones, and domed caps. */
  bool needsLiftedChords(slab::FaceHandle f) const
  {
    return inMixed(f) || (isCapFace(f) && capZ[f->info().component] != capLevelZ(f->info().component));
  }
  Point3 approximateLift(slab::FaceHandle f, int i, const MeshBuilder& mesh) const;

  // SteinerPlacement.cxx: points inside difference polygons.
  bool insertSteiner(const Point2& p, double z, MeshBuilder& mesh, double clearance = 0.0);
  /** Optional Steiner points keep this far (in 3D) from every contour (mm): closer, their triangles
   *  are slivers. */
  double optionalClearance() const { return 0.1 * typicalEdge; }
  std::size_t liftFlatChords(MeshBuilder& mesh);
  std::size_t addRows(MeshBuilder& mesh, double edgeLength);
  std::size_t addCapRows(MeshBuilder& mesh, double edgeLength);
  /** Inserts the row points (point, height), in order, each that keeps 0.6 edge lengths (in 3D) from
   *  the lifted corners of the difference faces and from the row points kept before it, and whose face
   *  `accepts` takes, with the optional clearance; forgets the corner levels if any went in. */
  std::size_t insertRowPoints(const std::vector<std::pair<Point2, double>>& rowPoints, MeshBuilder& mesh,
                              double edgeLength, const std::function<bool(slab::FaceHandle)>& accepts);
  std::size_t refineBadTriangles(MeshBuilder& mesh, double minAngle, double edgeLength, std::size_t budget);

  // SurfaceMetricFlips.cxx: Lawson flips judged on the lifted triangles.
  /** Flips every improving edge, or where the triangulation just changed, only those that the
   *  change can have made improving: the edges around `around` to begin with, then wherever flips
   *  lead. `touched`, when given, gets the vertices of every flipped pair of triangles. */
  std::size_t flipTowardsSurfaceQuality(const MeshBuilder& mesh, const std::vector<slab::VertexHandle>* around = nullptr,
                                        std::vector<slab::VertexHandle>* touched = nullptr);

  // SlabEmission.cxx: the lifted triangles, the switch fans and the walls, appended to the mesh.
  void emitTriangles(MeshBuilder& mesh, int rows, ReconstructionStatistics& statistics);
  std::vector<std::int32_t> wallChain(int vertex, std::map<int, std::vector<std::int32_t>>& chains, int rows,
                                      MeshBuilder& mesh) const;
  void addWallStrip(const std::vector<std::int32_t>& from, const std::vector<std::int32_t>& to, MeshBuilder& mesh,
                    std::size_t& counter) const;
};

} // namespace slicemesh

#endif

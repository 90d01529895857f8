// Regions of one closed piece remeshed side by side: slabs along the slice axis first, then bands
// around the seams between them. Internal to the finishing; the remeshing itself is
// SurfaceRemeshing.cxx's.
#ifndef RemeshingRegions_h
#define RemeshingRegions_h

#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <vector>

namespace slicemesh
{

/** Triangles of one region of a mesh, with the index in the whole mesh of each of its vertices
 *  (-1: a vertex the region's remesh created). */
struct MeshRegion
{
  TriangleMesh mesh;
  std::vector<std::int32_t> origin;
};

/** The region of every triangle: slabs along z (the slice axis) of about `trianglesPerRegion`
 *  triangles each, cut at quantiles of the triangles' centroid heights, none of them (nor the
 *  first and last) thinner than `minimumHeight` (mm). Depends on the mesh only. */
std::vector<int> slabRegions(const TriangleMesh& mesh, std::size_t trianglesPerRegion, double minimumHeight,
                             int& count);

/** The regions in the order to remesh them side by side: the most work first, so that no large
 *  region is left to run alone on one thread at the end. A region's work is taken as its triangles
 *  plus the triangles of `targetEdgeLength` its area holds (what the remesh collapses and what it
 *  makes): a slab holding a flat cap, tiled with few large triangles, is split into four to five
 *  times as many and took seven times as long as a slab of as many tiled triangles on a wall. */
std::vector<std::size_t> mostWorkFirst(const TriangleMesh& mesh, const std::vector<int>& regionOf, int count,
                                       double targetEdgeLength); // regionOf: one per triangle, each -1 or below count

/** Whether each vertex lies on a seam: between triangles of two regions, or of a region and the
 *  rest (region -1). */
std::vector<char> seamVertices(const TriangleMesh& mesh, const std::vector<int>& regionOf);

/** The region of every triangle within `rings` rings of a seam vertex (`seam`: one flag per vertex), one region per set of such
 *  triangles joined by edges, numbered in the order of their first triangle; -1 elsewhere. Throws for
 *  a mesh of more triangles than 32 bits can number. */
std::vector<int> seamBands(const TriangleMesh& mesh, const std::vector<char>& seam, int rings, int& count);

/** The triangles of every region, in mesh order: region r's are ids[first[r]] .. ids[first[r + 1] - 1]
 *  (region -1's are not listed; every other number is below `count`). From one pass over `regionOf`,
 *  so that cutting a region out goes over its own triangles, not over the whole mesh's. */
struct RegionTriangles
{
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> ids;
};
RegionTriangles trianglesByRegion(const std::vector<int>& regionOf, int count);

/** The region made of the mesh's triangles [begin, end) (indices in increasing order), its vertices
 *  numbered in the order they first appear. */
MeshRegion extractRegion(const TriangleMesh& mesh, const std::uint32_t* begin, const std::uint32_t* end);

/** The triangles of region `region`, its vertices numbered in the order they first appear. */
MeshRegion extractRegion(const TriangleMesh& mesh, const std::vector<int>& regionOf, int region);

/** The mesh with every region's triangles replaced by `regions[r]`'s: vertices with an origin keep
 *  their index (their new position written there), new ones are appended region by region. The
 *  triangles of region -1 stay as they are; vertices no triangle uses any more stay too (see
 *  withoutUnusedVertices). */
TriangleMesh reassembleRegions(const TriangleMesh& mesh, const std::vector<int>& regionOf,
                               const std::vector<MeshRegion>& regions);

/** The mesh without the vertices no triangle uses, the others in their order. */
TriangleMesh withoutUnusedVertices(const TriangleMesh& mesh);

} // namespace slicemesh

#endif

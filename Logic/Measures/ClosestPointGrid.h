// The closest point of a triangle mesh to a query near a point already known on it: the remesh's
// projection onto the tiling, where each vertex has moved a fraction of an edge since its last point
// on it. Internal: CGAL stays out of the installed headers.
#ifndef ClosestPointGrid_h
#define ClosestPointGrid_h

#include "Core/MappedAllocator.h"
#include "Measures/TriangleMeshTree.h"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace slicemesh
{

/** The triangles of a mesh in a uniform grid of cubic cells (hashed: only the cells the surface
 *  passes through are stored). A query looks at shells of cells around its own, nearest first, and
 *  only within the distance of its hint (a point on the mesh) or of the closest point found so far,
 *  where CGAL's AABB tree descends from its root for every query: on the remesh's projections,
 *  whose hints lie a fraction of an edge away, that descent was most of the time. The point found is
 *  the one the tree finds (the closest, CGAL's projection onto the same triangle); two triangles
 *  exactly as close can differ in which gives it, so its last bits may differ from the tree's. A
 *  mesh of more triangles than an entry can name (2^25) is searched through an AABB tree instead.
 *  The mesh must outlive the grid; queries may run side by side. */
class ClosestPointGrid
{
public:
  using Point = CgalKernel::Point_3;

  explicit ClosestPointGrid(const TriangleMesh& mesh);
  ~ClosestPointGrid();
  ClosestPointGrid(const ClosestPointGrid&) = delete;
  ClosestPointGrid& operator=(const ClosestPointGrid&) = delete;

  /** The closest point of the mesh to `query`; `hint`, a point on the mesh, bounds the search. */
  Point closestPoint(const Point& query, const Point& hint) const;
  /** The same without a hint. */
  Point closestPoint(const Point& query) const;

  double cellSize() const { return m_CellSize; }

private:
  /** A triangle's box, rounded outwards to floats: a lower bound of its distance is all it gives. */
  struct Box
  {
    std::array<float, 3> low, high;
  };

  Point search(const Point& query, const std::optional<Point>& hint) const;
  std::uint64_t keyOf(const std::array<std::int64_t, 3>& cell) const;
  std::array<std::int64_t, 3> cellOf(const std::array<double, 3>& p) const;
  /** The entries [first, last) of the cell's triangles, empty if the surface does not pass it. */
  std::pair<std::uint32_t, std::uint32_t> cellEntries(std::uint64_t key) const;
  const TriangleMeshTree& tree() const;

  const TriangleMesh& m_Mesh;
  double m_CellSize = 1.0;
  std::array<double, 3> m_Origin{};
  template <typename T>
  using Array = std::vector<T, MappedAllocator<T>>; ///< freed back to the kernel (MappedAllocator)
  Array<Box> m_Boxes;
  Array<std::uint64_t> m_CellKeys;  ///< the stored cells, sorted
  Array<std::uint32_t> m_CellStart; ///< the first entry of each stored cell, and the end
  Array<std::uint64_t> m_Entries;   ///< cell by cell: the cell's key, then its triangle's number
  Array<std::int32_t> m_Slots;      ///< open addressing: the stored cell's number, or -1
  mutable std::once_flag m_TreeBuilt;
  mutable std::unique_ptr<TriangleMeshTree> m_Tree;
};

} // namespace slicemesh

#endif

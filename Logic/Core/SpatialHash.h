// A uniform grid of square cells over the plane, each cell holding indices into the caller's items:
// the one spatial hash of the stages (nearest segments, candidate pairs of edges, points near a point).
// Cells are hashed, so the grid has no bounds and costs nothing where it is empty.
#ifndef SpatialHash_h
#define SpatialHash_h

#include "Core/PlanarGeometry.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace slicemesh
{

class SpatialHash
{
public:
  /** The cells (x, y) with x0 <= x <= x1 and y0 <= y <= y1. */
  struct CellRange
  {
    long long x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  };

  /** cellSize: the side of a cell (mm), positive; cell k along an axis is [k cellSize, (k + 1) cellSize). */
  explicit SpatialHash(double cellSize)
    : m_CellSize(cellSize)
  {
  }

  double cellSize() const { return m_CellSize; }
  long long cellOf(double v) const { return static_cast<long long>(std::floor(v / m_CellSize)); }
  /** The cells a box touches. */
  CellRange cellsOf(const Box2& box) const
  {
    return { cellOf(box.xmin), cellOf(box.xmax), cellOf(box.ymin), cellOf(box.ymax) };
  }
  /** The cells that can hold a point within radius of p: ceil(radius / cellSize) cells on each side of p's. */
  CellRange cellsWithin(const Point2& p, double radius) const
  {
    const long long reach = static_cast<long long>(std::ceil(radius / m_CellSize));
    const long long x = cellOf(p.x), y = cellOf(p.y);
    return { x - reach, x + reach, y - reach, y + reach };
  }

  /** Adds index to the cell holding p. */
  void insert(const Point2& p, int index) { m_Cells[{ cellOf(p.x), cellOf(p.y) }].push_back(index); }
  /** Adds index to every cell of the range (x outer, y inner). */
  void insert(const CellRange& cells, int index)
  {
    for (long long x = cells.x0; x <= cells.x1; ++x)
      for (long long y = cells.y0; y <= cells.y1; ++y)
        m_Cells[{ x, y }].push_back(index);
  }

  /** The indices in cell (x, y), in the order they were inserted. */
  const std::vector<int>& cell(long long x, long long y) const
  {
    static const std::vector<int> none;
    auto it = m_Cells.find({ x, y });
    return it == m_Cells.end() ? none : it->second;
  }

  /** Calls visit(index) for the indices of the range's cells, cell by cell (x outer, y inner), each
   *  cell in insertion order: an index held by several of the cells comes once for each. */
  template <typename Visit>
  void forEachIn(const CellRange& cells, Visit&& visit) const
  {
    anyIn(cells, [&](int index) {
      visit(index);
      return false;
    });
  }

  /** Whether test(index) holds for an index of the range's cells, taken in forEachIn's order up to
   *  the first that passes. */
  template <typename Test>
  bool anyIn(const CellRange& cells, Test&& test) const
  {
    for (long long x = cells.x0; x <= cells.x1; ++x)
      for (long long y = cells.y0; y <= cells.y1; ++y)
        for (int index : cell(x, y))
          if (test(index))
            return true;
    return false;
  }

private:
  struct CellKey
  {
    long long x, y;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y; }
  };
  struct CellKeyHash
  {
    std::size_t operator()(const CellKey& k) const
    {
      return static_cast<std::size_t>(static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL ^
                                      static_cast<std::uint64_t>(k.y));
    }
  };

  double m_CellSize;
  std::unordered_map<CellKey, std::vector<int>, CellKeyHash> m_Cells;
};

} // namespace slicemesh

#endif

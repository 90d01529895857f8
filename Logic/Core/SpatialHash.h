// A uniform grid of square cells over the plane, each cell holding indices into the caller's items:
// the one spatial hash of the stages (nearest segments, candidate pairs of edges, points near a point).
// Cells are hashed, so the grid has no bounds and costs nothing where it is empty.
#ifndef SpatialHash_h
#define SpatialHash_h

#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  void insert(const Point2& p, int index) { listOf({ cellOf(p.x), cellOf(p.y) }).push_back(index); }
  /** Adds index to every cell of the range (x outer, y inner). */
  void insert(const CellRange& cells, int index)
  {
    for (long long x = cells.x0; x <= cells.x1; ++x)
      for (long long y = cells.y0; y <= cells.y1; ++y)
        listOf({ x, y }).push_back(index);
  }

  /** The indices in cell (x, y), in the order they were inserted; valid until the next insert. */
  const std::vector<int>& cell(long long x, long long y) const
  {
    static const std::vector<int> none;
    const std::int32_t list = find({ x, y });
    return list < 0 ? none : m_Lists[static_cast<std::size_t>(list)];
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

  /** The cells are found by open addressing (linear probing in a power-of-two table of list
   *  numbers): the lookups run in the inner loops of the tiling's nearest-segment and spacing
   *  queries, where a node-based map's pointer chase and prime-modulo bucket cost more than the
   *  distance tests they serve. */
  static std::size_t hashOf(const CellKey& k)
  {
    std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL ^
                      static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4FULL;
    h ^= h >> 29;
    return static_cast<std::size_t>(h);
  }

  /** The list number of cell k, or -1. */
  std::int32_t find(const CellKey& k) const
  {
    if (m_Slots.empty())
      return -1;
    const std::size_t mask = m_Slots.size() - 1;
    for (std::size_t slot = hashOf(k) & mask;; slot = (slot + 1) & mask)
    {
      const std::int32_t list = m_Slots[slot];
      if (list < 0 || m_Keys[static_cast<std::size_t>(list)] == k)
        return list;
    }
  }

  /** The list of cell k, made empty if the cell had none. */
  std::vector<int>& listOf(const CellKey& k)
  {
    if (2 * (m_Keys.size() + 1) > m_Slots.size())
      grow();
    const std::size_t mask = m_Slots.size() - 1;
    std::size_t slot = hashOf(k) & mask;
    for (; m_Slots[slot] >= 0; slot = (slot + 1) & mask)
      if (m_Keys[static_cast<std::size_t>(m_Slots[slot])] == k)
        return m_Lists[static_cast<std::size_t>(m_Slots[slot])];
    m_Slots[slot] = static_cast<std::int32_t>(m_Keys.size());
    m_Keys.push_back(k);
    m_Lists.emplace_back();
    return m_Lists.back();
  }

  /** Doubles the table (at least 16 slots) and places every cell again: at most half full. */
  void grow()
  {
    m_Slots.assign(std::max<std::size_t>(16, 2 * m_Slots.size()), -1);
    const std::size_t mask = m_Slots.size() - 1;
    for (std::size_t list = 0; list < m_Keys.size(); ++list)
    {
      std::size_t slot = hashOf(m_Keys[list]) & mask;
      while (m_Slots[slot] >= 0)
        slot = (slot + 1) & mask;
      m_Slots[slot] = static_cast<std::int32_t>(list);
    }
  }

  double m_CellSize;
  std::vector<std::int32_t> m_Slots; ///< list numbers; -1 for an empty slot
  std::vector<CellKey> m_Keys;       ///< the cell of each list
  std::vector<std::vector<int>> m_Lists;
};

} // namespace slicemesh

#endif

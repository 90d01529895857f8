// A uniform grid of square cells over the plane, or of cubes over space, each cell holding indices
// into the caller's items: the one spatial hash of the stages (nearest segments, candidate pairs of
// edges, points near a point, triangles near a triangle). Cells are hashed, so the grid has no bounds
// and costs nothing where it is empty. A planar grid is the grid of space's cells with z = 0.
#ifndef SpatialHash_h
#define SpatialHash_h

#include "Core/BoundingBox.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace slicemesh
{

class SpatialHash
{
public:
  /** The cells (x, y, z) with x0 <= x <= x1, y0 <= y <= y1 and z0 <= z <= z1 (z = 0 in the plane). */
  struct CellRange
  {
    long long x0 = 0, x1 = -1, y0 = 0, y1 = -1, z0 = 0, z1 = 0;
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
  /** The cells of space a box touches: for items whose plan says little (a surface's walls). */
  CellRange cellsOf(const BoundingBox& box) const
  {
    return { cellOf(box.low[0]), cellOf(box.high[0]), cellOf(box.low[1]),
             cellOf(box.high[1]), cellOf(box.low[2]), cellOf(box.high[2]) };
  }
  /** A box over more cells than this is best tried by every query rather than filed under each of
   *  them (a long sliver among short triangles). */
  static constexpr double mostCellsFiled = 64.0;
  /** How many cells of space a box touches, counted in floating point: no overflow for a box far
   *  wider than the cells, NaN for a box with a NaN corner (so `!(count <= limit)` holds). */
  double cellCountOf(const BoundingBox& box) const
  {
    double count = 1.0;
    for (int a = 0; a < 3; ++a)
      count *= std::floor(box.high[a] / m_CellSize) - std::floor(box.low[a] / m_CellSize) + 1.0;
    return count;
  }
  /** The cells that can hold a point within radius of p: ceil(radius / cellSize) cells on each side of p's. */
  CellRange cellsWithin(const Point2& p, double radius) const
  {
    const long long reach = static_cast<long long>(std::ceil(radius / m_CellSize));
    const long long x = cellOf(p.x), y = cellOf(p.y);
    return { x - reach, x + reach, y - reach, y + reach };
  }

  /** The indices of one cell, in the order they were inserted: a chain through the grid's entries. */
  class Cell
  {
  public:
    class Iterator
    {
    public:
      Iterator(const SpatialHash* grid, std::int32_t entry) : m_Grid(grid), m_Entry(entry) {}
      int operator*() const { return m_Grid->m_Entries[static_cast<std::size_t>(m_Entry)].index; }
      Iterator& operator++()
      {
        m_Entry = m_Grid->m_Entries[static_cast<std::size_t>(m_Entry)].next;
        return *this;
      }
      bool operator!=(const Iterator& o) const { return m_Entry != o.m_Entry; }

    private:
      const SpatialHash* m_Grid;
      std::int32_t m_Entry;
    };
    Cell(const SpatialHash* grid, std::int32_t first) : m_Grid(grid), m_First(first) {}
    Iterator begin() const { return { m_Grid, m_First }; }
    Iterator end() const { return { m_Grid, -1 }; }

  private:
    const SpatialHash* m_Grid;
    std::int32_t m_First;
  };

  /** Adds index to the cell holding p. */
  void insert(const Point2& p, int index) { append({ cellOf(p.x), cellOf(p.y), 0 }, index); }
  /** Adds index to every cell of the range (x outer, z inner). */
  void insert(const CellRange& cells, int index)
  {
    for (long long x = cells.x0; x <= cells.x1; ++x)
      for (long long y = cells.y0; y <= cells.y1; ++y)
        for (long long z = cells.z0; z <= cells.z1; ++z)
          append({ x, y, z }, index);
  }

  /** The indices in cell (x, y, z), in the order they were inserted; valid until the next insert. */
  Cell cell(long long x, long long y, long long z = 0) const
  {
    const std::int32_t list = find({ x, y, z });
    return { this, list < 0 ? -1 : m_Ends[static_cast<std::size_t>(list)].first };
  }

  /** Calls visit(index) for the indices of the range's cells, cell by cell (x outer, z inner), each
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
        for (long long z = cells.z0; z <= cells.z1; ++z)
          for (int index : cell(x, y, z))
            if (test(index))
              return true;
    return false;
  }

private:
  struct CellKey
  {
    long long x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
  };

  /** The cells are found by open addressing (linear probing in a power-of-two table of list
   *  numbers): the lookups run in the inner loops of the tiling's nearest-segment and spacing
   *  queries, where a node-based map's pointer chase and prime-modulo bucket cost more than the
   *  distance tests they serve. */
  static std::size_t hashOf(const CellKey& k)
  {
    std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL ^
                      static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4FULL ^
                      static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ULL;
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

  /** Appends index to cell k's chain, starting the chain if the cell had none. */
  void append(const CellKey& k, int index)
  {
    if (2 * (m_Keys.size() + 1) > m_Slots.size())
      grow();
    const auto entry = static_cast<std::int32_t>(m_Entries.size());
    m_Entries.push_back({ index, -1 });
    const std::size_t mask = m_Slots.size() - 1;
    std::size_t slot = hashOf(k) & mask;
    for (; m_Slots[slot] >= 0; slot = (slot + 1) & mask)
      if (m_Keys[static_cast<std::size_t>(m_Slots[slot])] == k)
      {
        std::pair<std::int32_t, std::int32_t>& ends = m_Ends[static_cast<std::size_t>(m_Slots[slot])];
        m_Entries[static_cast<std::size_t>(ends.second)].next = entry;
        ends.second = entry;
        return;
      }
    m_Slots[slot] = static_cast<std::int32_t>(m_Keys.size());
    m_Keys.push_back(k);
    m_Ends.emplace_back(entry, entry);
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
  /** The indices of every cell in two arrays, each cell a chain through them (its first and last
   *  entry in m_Ends). With a vector per cell the allocator had 4.3% of the samples of a large
   *  structure set's BODY, 2.3% with the chains. */
  struct Entry
  {
    int index;
    std::int32_t next; ///< the cell's next entry; -1 after its last
  };
  std::vector<Entry> m_Entries;
  std::vector<std::pair<std::int32_t, std::int32_t>> m_Ends; ///< first and last entry of each list
};

} // namespace slicemesh

#endif

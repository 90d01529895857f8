#include "Measures/ClosestPointGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slicemesh
{
namespace
{

/** A cell is named by 13 bits per axis and an entry by its cell and a 25-bit triangle number, so
 *  that the entries sort as one 64-bit word each. */
constexpr int cellBits = 13;
constexpr std::int64_t cellsPerAxis = std::int64_t(1) << cellBits;
constexpr int triangleBits = 25;
constexpr std::uint64_t triangleMask = (std::uint64_t(1) << triangleBits) - 1;

/** More cells than this around a query and it goes to the tree: its hint was far away. */
constexpr std::int64_t mostCellsSearched = 64;

float below(double v)
{
  const float f = static_cast<float>(v);
  return static_cast<double>(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}

float above(double v)
{
  const float f = static_cast<float>(v);
  return static_cast<double>(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

std::uint64_t mix(std::uint64_t key)
{
  key *= 0x9E3779B97F4A7C15ULL;
  return key ^ (key >> 31);
}

} // namespace

ClosestPointGrid::ClosestPointGrid(const TriangleMesh& mesh)
  : m_Mesh(mesh)
{
  const std::size_t n = mesh.triangles.size();
  if (n == 0 || n > triangleMask)
    return; // every query goes to the tree
  m_Boxes.resize(n);
  std::array<double, 3> low{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity() };
  std::array<double, 3> high{ -low[0], -low[1], -low[2] };
  std::vector<float> extents(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    Box& box = m_Boxes[t];
    float largest = 0.0f;
    for (int axis = 0; axis < 3; ++axis)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (std::int32_t v : mesh.triangles[t])
      {
        const Point3& p = mesh.points[static_cast<std::size_t>(v)];
        const double c = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
      box.low[axis] = below(lo);
      box.high[axis] = above(hi);
      low[axis] = std::min(low[axis], static_cast<double>(box.low[axis]));
      high[axis] = std::max(high[axis], static_cast<double>(box.high[axis]));
      largest = std::max(largest, box.high[axis] - box.low[axis]);
    }
    extents[t] = largest;
  }
  if (!(std::isfinite(low[0]) && std::isfinite(low[1]) && std::isfinite(low[2]) && std::isfinite(high[0]) &&
        std::isfinite(high[1]) && std::isfinite(high[2])))
  {
    m_Boxes.clear();
    return;
  }
  m_Origin = low;
  // Cells twice the median triangle's box: a triangle covers a few cells, a cell holds a few dozen
  // triangles. Larger while the boxes would cover more than eight cells each on average, or the
  // extent more cells than a key names.
  std::nth_element(extents.begin(), extents.begin() + static_cast<std::ptrdiff_t>(n / 2), extents.end());
  const double extent = std::max({ high[0] - low[0], high[1] - low[1], high[2] - low[2] });
  m_CellSize = std::max({ 2.0 * static_cast<double>(extents[n / 2]), extent / double(cellsPerAxis - 2), 1e-300 });
  for (;; m_CellSize *= 2.0)
  {
    std::uint64_t covered = 0;
    for (const Box& box : m_Boxes)
    {
      const auto lo = cellOf({ box.low[0], box.low[1], box.low[2] });
      const auto hi = cellOf({ box.high[0], box.high[1], box.high[2] });
      covered += static_cast<std::uint64_t>((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1));
    }
    if (covered <= 8 * n || m_CellSize >= extent)
      break;
  }
  std::vector<std::uint64_t> entries;
  for (std::size_t t = 0; t < n; ++t)
  {
    const Box& box = m_Boxes[t];
    const auto lo = cellOf({ box.low[0], box.low[1], box.low[2] });
    const auto hi = cellOf({ box.high[0], box.high[1], box.high[2] });
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
          entries.push_back(keyOf({ x, y, z }) << triangleBits | t);
  }
  std::sort(entries.begin(), entries.end());
  m_Triangles.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e)
  {
    const std::uint64_t key = entries[e] >> triangleBits;
    if (m_CellKeys.empty() || m_CellKeys.back() != key)
    {
      m_CellKeys.push_back(key);
      m_CellStart.push_back(static_cast<std::uint32_t>(e));
    }
    m_Triangles[e] = static_cast<std::uint32_t>(entries[e] & triangleMask);
  }
  m_CellStart.push_back(static_cast<std::uint32_t>(entries.size()));
  std::size_t slots = 16;
  while (slots < 2 * m_CellKeys.size())
    slots *= 2;
  m_Slots.assign(slots, -1);
  for (std::size_t c = 0; c < m_CellKeys.size(); ++c)
  {
    std::size_t slot = mix(m_CellKeys[c]) & (slots - 1);
    while (m_Slots[slot] >= 0)
      slot = (slot + 1) & (slots - 1);
    m_Slots[slot] = static_cast<std::int32_t>(c);
  }
}

ClosestPointGrid::~ClosestPointGrid() = default;

std::array<std::int64_t, 3> ClosestPointGrid::cellOf(const std::array<double, 3>& p) const
{
  std::array<std::int64_t, 3> cell{};
  for (int axis = 0; axis < 3; ++axis)
  {
    const double c = std::floor((p[axis] - m_Origin[axis]) / m_CellSize);
    cell[axis] = static_cast<std::int64_t>(std::clamp(c, 0.0, double(cellsPerAxis - 1)));
  }
  return cell;
}

std::uint64_t ClosestPointGrid::keyOf(const std::array<std::int64_t, 3>& cell) const
{
  return static_cast<std::uint64_t>(cell[0]) << (2 * cellBits) | static_cast<std::uint64_t>(cell[1]) << cellBits |
         static_cast<std::uint64_t>(cell[2]);
}

std::pair<std::uint32_t, std::uint32_t> ClosestPointGrid::cellEntries(std::uint64_t key) const
{
  const std::size_t mask = m_Slots.size() - 1;
  for (std::size_t slot = mix(key) & mask;; slot = (slot + 1) & mask)
  {
    const std::int32_t c = m_Slots[slot];
    if (c < 0)
      return { 0, 0 };
    if (m_CellKeys[static_cast<std::size_t>(c)] == key)
      return { m_CellStart[static_cast<std::size_t>(c)], m_CellStart[static_cast<std::size_t>(c) + 1] };
  }
}

const TriangleMeshTree& ClosestPointGrid::tree() const
{
  std::call_once(m_TreeBuilt,
                 [this]
                 {
                   m_Tree = std::make_unique<TriangleMeshTree>();
                   insertTriangles(*m_Tree, m_Mesh);
                   m_Tree->build();
                 });
  return *m_Tree;
}

ClosestPointGrid::Point ClosestPointGrid::closestPoint(const Point& query) const
{
  return tree().closest_point(query);
}

ClosestPointGrid::Point ClosestPointGrid::closestPoint(const Point& query, const Point& hint) const
{
  if (m_Slots.empty())
    return slicemesh::closestPoint(tree(), query, hint);
  // As ClosestPointSearch: a triangle whose box lies beyond the closest point so far (with a margin
  // far above rounding) cannot give a closer one.
  const double margin = 1e-9 * (1.0 + std::max({ std::abs(query.x()), std::abs(query.y()), std::abs(query.z()) }));
  double reach = std::sqrt(CGAL::squared_distance(query, hint)) + margin;
  const std::array<double, 3> q{ query.x(), query.y(), query.z() };
  const auto lo = cellOf({ q[0] - reach, q[1] - reach, q[2] - reach });
  const auto hi = cellOf({ q[0] + reach, q[1] + reach, q[2] + reach });
  if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > mostCellsSearched)
    return slicemesh::closestPoint(tree(), query, hint);
  const CgalKernel kernel;
  const auto project = kernel.construct_projected_point_3_object();
  const auto compare = kernel.compare_distance_3_object();
  Point closest = hint;
  double reachSquared = reach * reach;
  auto searchCell = [&](const std::array<std::int64_t, 3>& cell)
  {
    const auto [first, last] = cellEntries(keyOf(cell));
    for (std::uint32_t e = first; e < last; ++e)
    {
      const std::uint32_t t = m_Triangles[e];
      const Box& box = m_Boxes[t];
      double boxDistance = 0.0;
      for (int axis = 0; axis < 3; ++axis)
      {
        const double outside = std::max({ static_cast<double>(box.low[axis]) - q[axis],
                                          q[axis] - static_cast<double>(box.high[axis]), 0.0 });
        boxDistance += outside * outside;
      }
      if (boxDistance > reachSquared)
        continue;
      const Point candidate = project(get(TriangleOfMesh{ &m_Mesh }, t), query);
      // CGAL's rule (AABB_traits::Closest_point): the candidate unless it is farther.
      if (compare(query, candidate, closest) != CGAL::LARGER && candidate != closest)
      {
        closest = candidate;
        reach = std::sqrt(CGAL::squared_distance(query, closest)) + margin;
        reachSquared = reach * reach;
      }
    }
  };
  // The query's own cell first: the closest point is most often there, and once it is found the
  // other cells' triangles, and most of the cells, lie beyond it.
  const auto own = cellOf(q);
  searchCell(own);
  for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
    for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
      for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
      {
        const std::array<std::int64_t, 3> cell{ x, y, z };
        if (cell == own)
          continue;
        double cellDistance = 0.0;
        for (int axis = 0; axis < 3; ++axis)
        {
          const double low = m_Origin[axis] + static_cast<double>(cell[axis]) * m_CellSize;
          const double outside = std::max({ low - q[axis], q[axis] - (low + m_CellSize), 0.0 });
          cellDistance += outside * outside;
        }
        if (cellDistance > reachSquared) // a closer point of a triangle lies in a cell as close
          continue;
        searchCell(cell);
      }
  return closest;
}

} // namespace slicemesh

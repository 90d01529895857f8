#include "Measures/ClosestPointGrid.h"

#include "Core/GridCellSize.h"

#include "Core/BoundingBox.h"

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

/** More shells of cells than this around a query that has found nothing near and it looks at every
 *  triangle: it lies far from the surface. */
constexpr std::int64_t mostShells = 24;

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

/** The cell of p in a grid of cells of `size` from `origin`, clamped to the cells a key names. */
std::array<std::int64_t, 3> cellAt(const std::array<double, 3>& p, const std::array<double, 3>& origin, double size)
{
  std::array<std::int64_t, 3> cell{};
  for (int axis = 0; axis < 3; ++axis)
  {
    const double c = std::floor((p[axis] - origin[axis]) / size);
    cell[axis] = static_cast<std::int64_t>(std::clamp(c, 0.0, double(cellsPerAxis - 1)));
  }
  return cell;
}

} // namespace

ClosestPointGrid::ClosestPointGrid(const TriangleMesh& mesh)
  : m_Mesh(mesh)
{
  const std::size_t n = mesh.triangles.size();
  if (n == 0 || n > triangleMask)
    return; // every query goes to the tree (built on first use)
  m_Boxes.resize(n);
  BoundingBox all;
  const std::size_t stride = cellSizeSampleStride(n);
  std::vector<float> extents;
  extents.reserve(n / stride + 1);
  for (std::size_t t = 0; t < n; ++t)
  {
    const BoundingBox exact = boxOfTriangle(mesh, t);
    Box& box = m_Boxes[t];
    float largest = 0.0f;
    for (int axis = 0; axis < 3; ++axis)
    {
      box.low[axis] = below(exact.low[axis]);
      box.high[axis] = above(exact.high[axis]);
      largest = std::max(largest, box.high[axis] - box.low[axis]);
    }
    all.add(Point3{ box.low[0], box.low[1], box.low[2] }); // the grid covers the rounded boxes
    all.add(Point3{ box.high[0], box.high[1], box.high[2] });
    if (t % stride == 0)
      extents.push_back(largest);
  }
  const std::array<double, 3>& low = all.low;
  const std::array<double, 3>& high = all.high;
  if (!std::all_of(low.begin(), low.end(), [](double v) { return std::isfinite(v); }) ||
      !std::all_of(high.begin(), high.end(), [](double v) { return std::isfinite(v); }))
  {
    m_Boxes.clear();
    return;
  }
  m_Origin = low;
  // Cells twice the median triangle's box (chooseCellSize), and never more along the extent than a
  // key names.
  const double extent = std::max({ high[0] - low[0], high[1] - low[1], high[2] - low[2] });
  const CellSizeChoice choice =
    chooseCellSize(std::move(extents), n, extent, extent / double(cellsPerAxis - 2),
                   [&](double size)
                   {
                     std::uint64_t covered = 0;
                     for (const Box& box : m_Boxes)
                     {
                       const auto lo = cellAt({ box.low[0], box.low[1], box.low[2] }, low, size);
                       const auto hi = cellAt({ box.high[0], box.high[1], box.high[2] }, low, size);
                       covered += static_cast<std::uint64_t>((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1));
                     }
                     return covered;
                   });
  m_CellSize = choice.size;
  const std::uint64_t covered = choice.covered;
  // Every allocation below is made once at its final size, for the same reason.
  m_Entries.reserve(covered);
  for (std::size_t t = 0; t < n; ++t)
  {
    const Box& box = m_Boxes[t];
    const auto lo = cellOf({ box.low[0], box.low[1], box.low[2] });
    const auto hi = cellOf({ box.high[0], box.high[1], box.high[2] });
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
          m_Entries.push_back(keyOf({ x, y, z }) << triangleBits | t);
  }
  std::sort(m_Entries.begin(), m_Entries.end());
  std::size_t cells = 0;
  for (std::size_t e = 0; e < m_Entries.size(); ++e)
    cells += e == 0 || (m_Entries[e] >> triangleBits) != (m_Entries[e - 1] >> triangleBits);
  m_CellKeys.reserve(cells);
  m_CellStart.reserve(cells + 1);
  for (std::size_t e = 0; e < m_Entries.size(); ++e)
  {
    const std::uint64_t key = m_Entries[e] >> triangleBits;
    if (m_CellKeys.empty() || m_CellKeys.back() != key)
    {
      m_CellKeys.push_back(key);
      m_CellStart.push_back(static_cast<std::uint32_t>(e));
    }
  }
  m_CellStart.push_back(static_cast<std::uint32_t>(m_Entries.size()));
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
  return cellAt(p, m_Origin, m_CellSize);
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
  return search(query, std::nullopt);
}

ClosestPointGrid::Point ClosestPointGrid::closestPoint(const Point& query, const Point& hint) const
{
  return search(query, hint);
}

ClosestPointGrid::Point ClosestPointGrid::search(const Point& query, const std::optional<Point>& hint) const
{
  // As ClosestPointSearch: a triangle whose box lies beyond the closest point so far (with a margin
  // far above rounding) cannot give a closer one.
  const double margin = 1e-9 * (1.0 + std::max({ std::abs(query.x()), std::abs(query.y()), std::abs(query.z()) }));
  std::optional<Point> closest = hint;
  double reach = hint ? std::sqrt(CGAL::squared_distance(query, *hint)) + margin : std::numeric_limits<double>::infinity();
  double reachSquared = reach * reach;
  const std::array<double, 3> q{ query.x(), query.y(), query.z() };
  const CgalKernel kernel;
  const auto project = kernel.construct_projected_point_3_object();
  const auto compare = kernel.compare_distance_3_object();
  auto consider = [&](std::uint32_t t)
  {
    const Box& box = m_Boxes[t];
    double boxDistance = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double outside = std::max({ static_cast<double>(box.low[axis]) - q[axis],
                                        q[axis] - static_cast<double>(box.high[axis]), 0.0 });
      boxDistance += outside * outside;
    }
    if (boxDistance > reachSquared)
      return;
    const Point candidate = project(get(TriangleOfMesh{ &m_Mesh }, t), query);
    // CGAL's rule (AABB_traits::Closest_point): the candidate unless it is farther.
    if (!closest || (compare(query, candidate, *closest) != CGAL::LARGER && candidate != *closest))
    {
      closest = candidate;
      reach = std::sqrt(CGAL::squared_distance(query, *closest)) + margin;
      reachSquared = reach * reach;
    }
  };
  if (m_Slots.empty()) // more triangles than an entry can name (or none): the tree
  {
    if (m_Mesh.triangles.empty())
      return query;
    return hint ? slicemesh::closestPoint(tree(), query, *hint) : tree().closest_point(query);
  }
  // Shells of cells around the query's own, nearest first, until the closest point found lies
  // nearer than any cell not searched yet: after shell r, everything outside lies at least r cell
  // sides away. A query far from the surface (no hint, or a hint many cells away) that still has found
  // nothing after a few dozen shells looks at every triangle instead.
  const auto own = cellOf(q);
  const std::int64_t last = cellsPerAxis - 1;
  for (std::int64_t r = 0;; ++r)
  {
    if (r > 0 && reach <= static_cast<double>(r - 1) * m_CellSize)
      break;
    if (own[0] - r < 0 && own[1] - r < 0 && own[2] - r < 0 && own[0] + r > last && own[1] + r > last && own[2] + r > last)
      break; // the whole grid searched
    if (r > mostShells)
    {
      for (std::uint32_t t = 0; t < m_Boxes.size(); ++t)
        consider(t);
      break;
    }
    for (std::int64_t x = own[0] - r; x <= own[0] + r; ++x)
      for (std::int64_t y = own[1] - r; y <= own[1] + r; ++y)
        for (std::int64_t z = own[2] - r; z <= own[2] + r; ++z)
        {
          const bool onShell = std::max({ std::abs(x - own[0]), std::abs(y - own[1]), std::abs(z - own[2]) }) == r;
          if (!onShell || x < 0 || y < 0 || z < 0 || x > last || y > last || z > last)
            continue;
          const std::array<std::int64_t, 3> cell{ x, y, z };
          double cellDistance = 0.0;
          for (int axis = 0; axis < 3; ++axis)
          {
            const double low = m_Origin[axis] + static_cast<double>(cell[axis]) * m_CellSize;
            const double outside = std::max({ low - q[axis], q[axis] - (low + m_CellSize), 0.0 });
            cellDistance += outside * outside;
          }
          if (cellDistance > reachSquared) // a closer point of a triangle lies in a cell as close
            continue;
          const auto [first, end] = cellEntries(keyOf(cell));
          for (std::uint32_t e = first; e < end; ++e)
            consider(static_cast<std::uint32_t>(m_Entries[e] & triangleMask));
        }
  }
  return closest ? *closest : query;
}

} // namespace slicemesh

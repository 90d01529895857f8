#include "Measures/SelfIntersections.h"

#include "Core/BoundingBox.h"
#include "Core/ParallelFor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <mutex>

namespace slicemesh
{
namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

/** Cubic cells of one size over the boxes' extent; a cell is named by one 64-bit key. */
class CellGrid
{
public:
  CellGrid(const std::array<double, 3>& origin, double size)
    : m_Origin(origin)
    , m_Size(size)
  {
  }

  std::array<std::uint64_t, 3> cellOf(const std::array<double, 3>& p) const
  {
    std::array<std::uint64_t, 3> cell{};
    for (int k = 0; k < 3; ++k)
      cell[k] = static_cast<std::uint64_t>(std::max(0.0, std::floor((p[k] - m_Origin[k]) / m_Size)));
    return cell;
  }

  static std::uint64_t key(std::uint64_t x, std::uint64_t y, std::uint64_t z) { return (x << 42) | (y << 21) | z; }

  /** How many cells the box covers. */
  std::uint64_t cellsOf(const BoundingBox& box) const
  {
    const auto lo = cellOf(box.low), hi = cellOf(box.high);
    return (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  }

  double size() const { return m_Size; }

private:
  std::array<double, 3> m_Origin;
  double m_Size;
};

/** The grid's cell size: twice the median triangle's box, so that most boxes cover one to eight
 *  cells and a cell holds a few dozen triangles; doubled while the boxes would cover more than
 *  eight cells each on average (a mesh of a few long triangles). At most 2^21 cells along an axis. */
CellGrid gridFor(const std::vector<BoundingBox>& boxes, const BoundingBox& all)
{
  const double extent = std::max({ all.high[0] - all.low[0], all.high[1] - all.low[1], all.high[2] - all.low[2] });
  std::vector<double> sizes(boxes.size());
  for (std::size_t b = 0; b < boxes.size(); ++b)
    sizes[b] = std::max({ boxes[b].high[0] - boxes[b].low[0], boxes[b].high[1] - boxes[b].low[1],
                          boxes[b].high[2] - boxes[b].low[2] });
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
  double size = std::max({ 2.0 * sizes[sizes.size() / 2], extent / double(1 << 20), 1e-300 });
  for (;; size *= 2.0)
  {
    const CellGrid grid(all.low, size);
    std::uint64_t covered = 0;
    for (const BoundingBox& box : boxes)
      covered += grid.cellsOf(box);
    if (covered <= 8 * boxes.size() || size >= extent)
      return grid;
  }
}

Point corner(const TriangleMesh& mesh, std::int32_t v)
{
  const Point3& p = mesh.points[static_cast<std::size_t>(v)];
  return { p.x, p.y, p.z };
}

/** Whether triangles a and b intersect other than along what they share (CGAL's rule, see the header). */
bool crossing(const TriangleMesh& mesh, std::size_t a, std::size_t b)
{
  const Triangle& s = mesh.triangles[a];
  const Triangle& t = mesh.triangles[b];
  int shared = 0, si = -1, ti = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j])
      {
        ++shared;
        si = i;
        ti = j;
      }
  if (shared >= 2)
  {
    // The corners opposite the common edge: the only corners of s and t not in the other.
    std::int32_t p = -1, q = -1;
    for (int i = 0; i < 3; ++i)
    {
      if (std::find(t.begin(), t.end(), s[i]) == t.end())
        p = s[i];
      if (std::find(s.begin(), s.end(), t[i]) == s.end())
        q = t[i];
    }
    if (p < 0 || q < 0)
      return false; // the same three corners twice: a topology fault, counted by the topology pass
    std::int32_t u = -1, v = -1;
    for (int i = 0; i < 3; ++i)
      if (s[i] != p)
        (u < 0 ? u : v) = s[i];
    const Point pu = corner(mesh, u), pv = corner(mesh, v), pp = corner(mesh, p), pq = corner(mesh, q);
    return CGAL::coplanar(pu, pv, pp, pq) && CGAL::coplanar_orientation(pu, pv, pp, pq) == CGAL::POSITIVE;
  }
  if (shared == 1)
  {
    const Point v = corner(mesh, s[si]);
    const Point sb = corner(mesh, s[(si + 1) % 3]), sc = corner(mesh, s[(si + 2) % 3]);
    const Point tb = corner(mesh, t[(ti + 1) % 3]), tc = corner(mesh, t[(ti + 2) % 3]);
    // t's other corners strictly on one side of s's plane: all of t but the common corner is, so
    // the two meet there only. Most pairs of a surface's neighbouring triangles end here.
    const CGAL::Orientation tbSide = CGAL::orientation(v, sb, sc, tb);
    if (tbSide != CGAL::COPLANAR && tbSide == CGAL::orientation(v, sb, sc, tc))
      return false;
    // Each edge opposite the common corner, against the other triangle.
    const Kernel::Triangle_3 ts(v, sb, sc), tt(v, tb, tc);
    return CGAL::do_intersect(ts, Kernel::Segment_3(tb, tc)) || CGAL::do_intersect(tt, Kernel::Segment_3(sb, sc));
  }
  const Kernel::Triangle_3 ts(corner(mesh, s[0]), corner(mesh, s[1]), corner(mesh, s[2]));
  const Kernel::Triangle_3 tt(corner(mesh, t[0]), corner(mesh, t[1]), corner(mesh, t[2]));
  return CGAL::do_intersect(ts, tt);
}

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> selfIntersectingTrianglePairs(const TriangleMesh& mesh,
                                                                               unsigned int threads)
{
  // Every step runs on ranges of triangles or cells side by side: on one thread, building the grid
  // took as long as testing the pairs on two.
  const std::size_t nTriangles = mesh.triangles.size();
  std::vector<BoundingBox> boxes(nTriangles);
  std::vector<char> degenerate(nTriangles, 0);
  parallelForRanges(nTriangles, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t t = first; t < last; ++t)
                      {
                        const Triangle& triangle = mesh.triangles[t];
                        degenerate[t] = CGAL::collinear(corner(mesh, triangle[0]), corner(mesh, triangle[1]),
                                                        corner(mesh, triangle[2]));
                        boxes[t] = boxOfTriangle(mesh, t);
                      }
                    });
  // Degenerate triangles are reported with themselves and left out of the boxes (as CGAL does).
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::uint32_t> boxed;
  BoundingBox all;
  for (std::size_t t = 0; t < nTriangles; ++t)
    if (degenerate[t])
      pairs.emplace_back(t, t);
    else
    {
      boxes[boxed.size()] = boxes[t];
      all.add(boxes[t]);
      boxed.push_back(static_cast<std::uint32_t>(t));
    }
  boxes.resize(boxed.size());
  if (boxes.size() < 2)
    return pairs;

  // Every box in every cell it covers, grouped by cell: the entries are dealt into a fixed number of
  // bins by their cell, each bin sorted on its own. Which bin a cell falls in does not matter, since
  // the pairs found are sorted at the end.
  const CellGrid grid = gridFor(boxes, all);
  constexpr std::size_t bins = 256;
  auto binOf = [](std::uint64_t key) { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 56); };
  auto forEachCell = [&grid](const BoundingBox& box, auto&& visit)
  {
    const auto from = grid.cellOf(box.low), to = grid.cellOf(box.high);
    for (std::uint64_t x = from[0]; x <= to[0]; ++x)
      for (std::uint64_t y = from[1]; y <= to[1]; ++y)
        for (std::uint64_t z = from[2]; z <= to[2]; ++z)
          visit(CellGrid::key(x, y, z));
  };
  // Ranges of boxes fixed by the count alone, so that the layout does not depend on the threads.
  constexpr std::size_t boxesPerRange = 16384;
  const std::size_t ranges = fixedRangeCount(boxes.size(), boxesPerRange);
  std::vector<std::size_t> counts(ranges * bins, 0);
  parallelForFixedRanges(boxes.size(), boxesPerRange, threads,
                         [&](std::size_t r, std::size_t firstBox, std::size_t lastBox)
                         {
                           for (std::size_t b = firstBox; b < lastBox; ++b)
                             forEachCell(boxes[b], [&](std::uint64_t key) { ++counts[r * bins + binOf(key)]; });
                         });
  // Bin by bin, range by range: where each range's entries of each bin go.
  std::vector<std::size_t> binStart(bins + 1, 0), next(ranges * bins);
  for (std::size_t bin = 0, at = 0; bin < bins; ++bin)
  {
    binStart[bin] = at;
    for (std::size_t r = 0; r < ranges; ++r)
    {
      next[r * bins + bin] = at;
      at += counts[r * bins + bin];
    }
    binStart[bin + 1] = at;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries(binStart[bins]);
  parallelForFixedRanges(boxes.size(), boxesPerRange, threads,
                         [&](std::size_t r, std::size_t firstBox, std::size_t lastBox)
                         {
                           for (std::size_t b = firstBox; b < lastBox; ++b)
                             forEachCell(boxes[b], [&](std::uint64_t key)
                                         { entries[next[r * bins + binOf(key)]++] = { key, static_cast<std::uint32_t>(b) }; });
                         });
  parallelFor(bins, threads,
              [&](std::size_t bin)
              {
                std::sort(entries.begin() + static_cast<std::ptrdiff_t>(binStart[bin]),
                          entries.begin() + static_cast<std::ptrdiff_t>(binStart[bin + 1]));
              });
  std::vector<std::size_t> groupStart;
  for (std::size_t e = 0; e < entries.size(); ++e)
    if (e == 0 || entries[e].first != entries[e - 1].first)
      groupStart.push_back(e);
  groupStart.push_back(entries.size());
  // Each pair of overlapping boxes is tested once: in the cell of the lower corner of their overlap,
  // which is the larger of the two boxes' lower cells along each axis (a cell index only grows with
  // the coordinate), taken per box once here rather than per pair.
  std::vector<std::array<std::uint64_t, 3>> lowCell(boxes.size());
  parallelForRanges(boxes.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t b = first; b < last; ++b)
                        lowCell[b] = grid.cellOf(boxes[b].low);
                    });
  std::mutex found;
  parallelForRanges(groupStart.size() - 1, threads,
                    [&](std::size_t firstGroup, std::size_t lastGroup)
                    {
                      std::vector<std::pair<std::size_t, std::size_t>> local;
                      for (std::size_t g = firstGroup; g < lastGroup; ++g)
                        for (std::size_t i = groupStart[g]; i < groupStart[g + 1]; ++i)
                          for (std::size_t j = i + 1; j < groupStart[g + 1]; ++j)
                          {
                            const std::uint32_t ba = entries[i].second, bb = entries[j].second;
                            if (!boxes[ba].overlaps(boxes[bb]))
                              continue;
                            const auto& ca = lowCell[ba];
                            const auto& cb = lowCell[bb];
                            if (CellGrid::key(std::max(ca[0], cb[0]), std::max(ca[1], cb[1]), std::max(ca[2], cb[2])) !=
                                entries[i].first)
                              continue;
                            const std::size_t ta = boxed[ba], tb = boxed[bb];
                            if (crossing(mesh, ta, tb))
                              local.emplace_back(std::min(ta, tb), std::max(ta, tb));
                          }
                      const std::lock_guard<std::mutex> lock(found);
                      pairs.insert(pairs.end(), local.begin(), local.end());
                    },
                    64);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace slicemesh

#include "Measures/SelfIntersections.h"

#include "Core/BoundingBox.h"
#include "Core/DefaultInitAllocator.h"
#include "Core/GridCellSize.h"
#include "Core/ParallelFor.h"
#include "Measures/TrianglesMeetingBoxes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <numeric>

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
  /** The cell's x and y indices from its key (key's inverse, but for z). */
  static std::uint64_t xOfKey(std::uint64_t key) { return key >> 42; }
  static std::uint64_t yOfKey(std::uint64_t key) { return (key >> 21) & ((std::uint64_t(1) << 21) - 1); }

  /** How many cells the box covers. */
  std::uint64_t cellsOf(const BoundingBox& box) const
  {
    const auto lo = cellOf(box.low), hi = cellOf(box.high);
    return (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  }

  double size() const { return m_Size; }

  /** Calls visit(key) for each cell the box covers, until a call returns true; whether one did. */
  template <typename Visit>
  bool anyCovered(const BoundingBox& box, Visit&& visit) const
  {
    const auto from = cellOf(box.low), to = cellOf(box.high);
    for (std::uint64_t x = from[0]; x <= to[0]; ++x)
      for (std::uint64_t y = from[1]; y <= to[1]; ++y)
        for (std::uint64_t z = from[2]; z <= to[2]; ++z)
          if (visit(key(x, y, z)))
            return true;
    return false;
  }

private:
  std::array<double, 3> m_Origin;
  double m_Size;
};

/** The grid over `count` boxes, box b being boxOf(b) (chooseCellSize), at most 2^21 cells along an
 *  axis as a key names. */
template <typename BoxOf>
CellGrid gridFor(BoxOf&& boxOf, std::size_t count, const BoundingBox& all, unsigned int threads)
{
  const double extent = std::max({ all.high[0] - all.low[0], all.high[1] - all.low[1], all.high[2] - all.low[2] });
  std::vector<double> sides;
  for (std::size_t b = 0; b < count; b += cellSizeSampleStride(count))
  {
    const BoundingBox box = boxOf(b);
    sides.push_back(std::max({ box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2] }));
  }
  const CellSizeChoice choice = chooseCellSize(std::move(sides), count, extent, extent / double(1 << 20),
                                               [&](double size)
                                               {
                                                 const CellGrid grid(all.low, size);
                                                 const std::vector<std::uint64_t> covered =
                                                   fixedRangeResults<std::uint64_t>(
                                                     count, 65536, threads,
                                                     [&](std::uint64_t& sum, std::size_t first, std::size_t last)
                                                     {
                                                       for (std::size_t b = first; b < last; ++b)
                                                         sum += grid.cellsOf(boxOf(b));
                                                     });
                                                 return std::accumulate(covered.begin(), covered.end(), std::uint64_t(0));
                                               });
  return CellGrid(all.low, choice.size);
}

/** A box filed under one cell of the grid (the cell's key), in the order of cell, then box. */
struct CellEntry
{
  std::uint64_t key;
  std::uint32_t box;
  bool operator<(const CellEntry& other) const { return key != other.key ? key < other.key : box < other.box; }
};

/** A triangle as the pair test reads it: its corners' vertex numbers and points. */
struct TriangleCorners
{
  Triangle ids;
  std::array<Point3, 3> points;

  Point at(int corner) const
  {
    const Point3& p = points[static_cast<std::size_t>(corner)];
    return { p.x, p.y, p.z };
  }
};

/** A triangle's box in one cell of the grid, with what the pair test needs of it. A cell's triangles
 *  are copied side by side before each is compared with every other there: read through the mesh,
 *  their boxes and corners were scattered over memory, and waiting for them was most of the test's
 *  time (a fifth less time for the test on the thick scaling ellipsoid's finished surface). */
struct CellMember
{
  BoundingBox box;
  std::array<std::uint64_t, 3> lowCell; ///< the cell of the box's lower corner
  std::size_t triangle;
  TriangleCorners corners;
};

/** BoundingBox::overlaps without a branch per axis: most pairs in a cell are apart along one axis
 *  or another, and which one was not predictable. */
inline bool overlap(const BoundingBox& a, const BoundingBox& b)
{
  return static_cast<bool>((a.low[0] <= b.high[0]) & (b.low[0] <= a.high[0]) & (a.low[1] <= b.high[1]) &
                           (b.low[1] <= a.high[1]) & (a.low[2] <= b.high[2]) & (b.low[2] <= a.high[2]));
}

TriangleCorners cornersOf(const std::vector<Point3>& points, const Triangle& ids)
{
  return { ids,
           { points[static_cast<std::size_t>(ids[0])], points[static_cast<std::size_t>(ids[1])],
             points[static_cast<std::size_t>(ids[2])] } };
}

TriangleCorners cornersOf(const TriangleMesh& mesh, std::size_t t)
{
  return cornersOf(mesh.points, mesh.triangles[t]);
}

Point corner(const TriangleMesh& mesh, std::int32_t v)
{
  const Point3& p = mesh.points[static_cast<std::size_t>(v)];
  return { p.x, p.y, p.z };
}

/** Whether triangles s and t intersect other than along what they share (CGAL's rule, see the header). */
bool crossing(const TriangleCorners& s, const TriangleCorners& t)
{
  int shared = 0, si = -1, ti = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.ids[i] == t.ids[j])
      {
        ++shared;
        si = i;
        ti = j;
      }
  if (shared >= 2)
  {
    // The corners opposite the common edge: the only corners of s and t not in the other.
    int p = -1, q = -1;
    for (int i = 0; i < 3; ++i)
    {
      if (std::find(t.ids.begin(), t.ids.end(), s.ids[i]) == t.ids.end())
        p = i;
      if (std::find(s.ids.begin(), s.ids.end(), t.ids[i]) == s.ids.end())
        q = i;
    }
    if (p < 0 || q < 0)
      return false; // the same three corners twice: a topology fault, counted by the topology pass
    const int u = p == 0 ? 1 : 0, v = p == 2 ? 1 : 2; // s's other corners, in s's order
    const Point pu = s.at(u), pv = s.at(v), pp = s.at(p), pq = t.at(q);
    return CGAL::coplanar(pu, pv, pp, pq) && CGAL::coplanar_orientation(pu, pv, pp, pq) == CGAL::POSITIVE;
  }
  if (shared == 1)
  {
    const Point v = s.at(si);
    const Point sb = s.at((si + 1) % 3), sc = s.at((si + 2) % 3);
    const Point tb = t.at((ti + 1) % 3), tc = t.at((ti + 2) % 3);
    // t's other corners strictly on one side of s's plane: all of t but the common corner is, so
    // the two meet there only. Most pairs of a surface's neighbouring triangles end here.
    const CGAL::Orientation tbSide = CGAL::orientation(v, sb, sc, tb);
    if (tbSide != CGAL::COPLANAR && tbSide == CGAL::orientation(v, sb, sc, tc))
      return false;
    // Each edge opposite the common corner, against the other triangle.
    const Kernel::Triangle_3 ts(v, sb, sc), tt(v, tb, tc);
    return CGAL::do_intersect(ts, Kernel::Segment_3(tb, tc)) || CGAL::do_intersect(tt, Kernel::Segment_3(sb, sc));
  }
  const Kernel::Triangle_3 ts(s.at(0), s.at(1), s.at(2));
  const Kernel::Triangle_3 tt(t.at(0), t.at(1), t.at(2));
  return CGAL::do_intersect(ts, tt);
}

} // namespace

bool trianglesCross(const std::vector<Point3>& points, const Triangle& s, const Triangle& t)
{
  return crossing(cornersOf(points, s), cornersOf(points, t));
}

std::vector<std::pair<std::size_t, std::size_t>> selfIntersectingTrianglePairs(const TriangleMesh& mesh,
                                                                               unsigned int threads)
{
  return selfIntersectingTrianglePairsInGroups(mesh, 0, threads);
}

std::vector<std::pair<std::size_t, std::size_t>>
selfIntersectingTrianglePairsInGroups(const TriangleMesh& mesh, std::size_t entriesPerGroup, unsigned int threads)
{
  // Every step runs on ranges of triangles or cells side by side: on one thread, building the grid
  // took as long as testing the pairs on two.
  const std::size_t nTriangles = mesh.triangles.size();
  std::vector<char> degenerate(nTriangles, 0);
  parallelForRanges(nTriangles, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t t = first; t < last; ++t)
                      {
                        const Triangle& triangle = mesh.triangles[t];
                        degenerate[t] = CGAL::collinear(corner(mesh, triangle[0]), corner(mesh, triangle[1]),
                                                        corner(mesh, triangle[2]));
                      }
                    });
  // Degenerate triangles are reported with themselves and left out of the boxes (as CGAL does).
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::uint32_t> boxed;
  boxed.reserve(nTriangles);
  for (std::size_t t = 0; t < nTriangles; ++t)
    if (degenerate[t])
      pairs.emplace_back(t, t);
    else
      boxed.push_back(static_cast<std::uint32_t>(t));
  std::vector<char>().swap(degenerate); // freed: not held through the test
  if (boxed.size() < 2)
    return pairs;
  // A box is taken from its triangle's corners each time it is needed rather than held for every
  // triangle (48 bytes a triangle, a large piece's peak memory): the walks over the boxes read the
  // corners instead, at about the same speed.
  auto boxOf = [&](std::size_t b) { return boxOfTriangle(mesh, boxed[b]); };
  const std::vector<BoundingBox> rangeBoxes =
    fixedRangeResults<BoundingBox>(boxed.size(), 65536, threads,
                                   [&](BoundingBox& box, std::size_t first, std::size_t last)
                                   {
                                     for (std::size_t b = first; b < last; ++b)
                                       box.add(boxOf(b));
                                   });
  BoundingBox all;
  for (const BoundingBox& box : rangeBoxes)
    all.add(box);

  // Every box in every cell it covers, grouped by cell: the entries are dealt into a fixed number of
  // bins by their cell, each bin sorted on its own. A bin is a run of the grid's rows of cells along
  // z, taken in the order of x then y, so that the cells walked one after another are neighbours in
  // space, whose triangles (and the mesh's data for them) are mostly the same: dealt by a hash of the
  // cell, each cell's triangles were read from memory afresh, and that wait was most of the test's
  // time. (Runs of rows, not slabs across x: a surface one cell wide along x would be one bin.) The
  // pairs found are sorted at the end.
  const CellGrid grid = gridFor(boxOf, boxed.size(), all, threads);
  constexpr std::size_t bins = 256;
  const std::array<std::uint64_t, 3> lastCell = grid.cellOf(all.high);
  const std::uint64_t rowsAlongY = lastCell[1] + 1, rows = (lastCell[0] + 1) * rowsAlongY;
  auto binOf = [&](std::uint64_t key)
  {
    const std::uint64_t row = CellGrid::xOfKey(key) * rowsAlongY + CellGrid::yOfKey(key);
    return static_cast<std::size_t>(row * bins / rows);
  };
  // Ranges of boxes fixed by the count alone, so that the layout does not depend on the threads.
  constexpr std::size_t boxesPerRange = 16384;
  const std::size_t ranges = fixedRangeCount(boxed.size(), boxesPerRange);
  std::vector<std::size_t> counts(ranges * bins, 0);
  parallelForFixedRanges(boxed.size(), boxesPerRange, threads,
                         [&](std::size_t r, std::size_t firstBox, std::size_t lastBox)
                         {
                           for (std::size_t b = firstBox; b < lastBox; ++b)
                             grid.anyCovered(boxOf(b), [&](std::uint64_t key) {
                               ++counts[r * bins + binOf(key)];
                               return false;
                             });
                         });
  // The bins are filed and tested a group at a time, each group of about as many entries as there
  // are boxes: all at once, the entries (a box in each cell it covers, at most eight on average) were
  // most of the test's memory, and a run's peak came when a large piece was tested beside another
  // piece's smoothing. Filing a group costs one more walk over the boxes' cells.
  std::vector<std::size_t> entriesOfBin(bins, 0);
  for (std::size_t bin = 0; bin < bins; ++bin)
    for (std::size_t r = 0; r < ranges; ++r)
      entriesOfBin[bin] += counts[r * bins + bin];
  if (entriesPerGroup == 0)
    entriesPerGroup = std::max<std::size_t>(boxed.size(), std::size_t{ 1 } << 20);
  std::vector<std::size_t> groupStart{ 0 };
  std::size_t largestGroup = 0, inGroup = 0;
  for (std::size_t bin = 0; bin < bins; ++bin)
  {
    if (inGroup > 0 && inGroup + entriesOfBin[bin] > entriesPerGroup)
    {
      groupStart.push_back(bin);
      inGroup = 0;
    }
    inGroup += entriesOfBin[bin];
    largestGroup = std::max(largestGroup, inGroup);
  }
  groupStart.push_back(bins);
  std::vector<CellEntry, DefaultInitAllocator<CellEntry>> entries(largestGroup); // filled on every thread below
  std::vector<std::size_t> binStart(bins + 1, 0), next(ranges * bins);
  std::mutex found;
  for (std::size_t g = 0; g + 1 < groupStart.size(); ++g)
  {
    const std::size_t firstBin = groupStart[g], lastBin = groupStart[g + 1];
    // Bin by bin, range by range: where each range's entries of each bin of the group go.
    for (std::size_t bin = firstBin, at = 0; bin < lastBin; ++bin)
    {
      binStart[bin] = at;
      for (std::size_t r = 0; r < ranges; ++r)
      {
        next[r * bins + bin] = at;
        at += counts[r * bins + bin];
      }
      binStart[bin + 1] = at;
    }
    parallelForFixedRanges(boxed.size(), boxesPerRange, threads,
                           [&](std::size_t r, std::size_t firstBox, std::size_t lastBox)
                           {
                             for (std::size_t b = firstBox; b < lastBox; ++b)
                               grid.anyCovered(boxOf(b), [&](std::uint64_t key) {
                                 const std::size_t bin = binOf(key);
                                 if (bin >= firstBin && bin < lastBin)
                                   entries[next[r * bins + bin]++] = { key, static_cast<std::uint32_t>(b) };
                                 return false;
                               });
                           });
    parallelFor(lastBin - firstBin, threads,
                [&](std::size_t i)
                {
                  const std::size_t bin = firstBin + i;
                  std::sort(entries.begin() + static_cast<std::ptrdiff_t>(binStart[bin]),
                            entries.begin() + static_cast<std::ptrdiff_t>(binStart[bin + 1]));
                });
    // Bin by bin side by side: a cell's entries all lie in its bin, together once the bin is sorted.
    // Each pair of overlapping boxes is tested once: in the cell of the lower corner of their
    // overlap, which is the larger of the two boxes' lower cells along each axis (a cell index only
    // grows with the coordinate).
    parallelFor(lastBin - firstBin, threads,
                [&](std::size_t i)
                {
                  const std::size_t bin = firstBin + i;
                  std::vector<std::pair<std::size_t, std::size_t>> local;
                  std::vector<CellMember> members;
                  std::vector<std::pair<double, std::uint32_t>> byLowX;
                  for (std::size_t e = binStart[bin]; e < binStart[bin + 1];)
                  {
                    const std::uint64_t cell = entries[e].key;
                    members.clear(); // the cell's triangles, copied side by side (CellMember)
                    for (; e < binStart[bin + 1] && entries[e].key == cell; ++e)
                    {
                      const std::uint32_t b = entries[e].box;
                      const BoundingBox box = boxOf(b);
                      members.push_back({ box, grid.cellOf(box.low), boxed[b], cornersOf(mesh, boxed[b]) });
                    }
                    // Swept along x: each box meets only those that start before it ends, so the
                    // pairs are taken from the cell's boxes in order of their low x, each against the
                    // next ones until one starts past its high x (every pair of a cell of a few dozen
                    // boxes compared was most of the test's time).
                    byLowX.clear();
                    for (std::size_t m = 0; m < members.size(); ++m) // a box of no number first: it meets none
                      byLowX.emplace_back(std::isnan(members[m].box.low[0]) ? -std::numeric_limits<double>::infinity()
                                                                             : members[m].box.low[0],
                                          static_cast<std::uint32_t>(m));
                    std::sort(byLowX.begin(), byLowX.end());
                    for (std::size_t m = 0; m < byLowX.size(); ++m)
                      for (std::size_t n = m + 1; n < byLowX.size() && byLowX[n].first <= members[byLowX[m].second].box.high[0]; ++n)
                      {
                        const CellMember& a = members[byLowX[m].second];
                        const CellMember& b = members[byLowX[n].second];
                        if (!overlap(a.box, b.box))
                          continue;
                        if (CellGrid::key(std::max(a.lowCell[0], b.lowCell[0]), std::max(a.lowCell[1], b.lowCell[1]),
                                          std::max(a.lowCell[2], b.lowCell[2])) != cell)
                          continue;
                        if (crossing(a.corners, b.corners))
                          local.emplace_back(std::min(a.triangle, b.triangle), std::max(a.triangle, b.triangle));
                      }
                  }
                  if (local.empty())
                    return;
                  const std::lock_guard<std::mutex> lock(found);
                  pairs.insert(pairs.end(), local.begin(), local.end());
                });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::pair<std::size_t, std::size_t>>
selfIntersectingTrianglePairsAfterMoving(const TriangleMesh& mesh,
                                         const std::vector<std::pair<std::size_t, std::size_t>>& before,
                                         const std::vector<char>& moved, unsigned int threads)
{
  const std::size_t nTriangles = mesh.triangles.size();
  std::vector<char> movedTriangle(nTriangles, 0);
  std::vector<std::size_t> movedTriangles;
  for (std::size_t t = 0; t < nTriangles; ++t)
    for (std::int32_t v : mesh.triangles[t])
      if (moved[static_cast<std::size_t>(v)])
      {
        movedTriangle[t] = 1;
        movedTriangles.push_back(t);
        break;
      }
  // Past a tenth of the mesh, sifting the rest for the triangles near the moved ones costs about
  // what the whole test does.
  if (10 * movedTriangles.size() > nTriangles)
    return selfIntersectingTrianglePairs(mesh, threads);

  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& pair : before)
    if (!movedTriangle[pair.first] && !movedTriangle[pair.second])
      pairs.push_back(pair);
  auto isDegenerate = [&](std::size_t t)
  {
    const Triangle& triangle = mesh.triangles[t];
    return CGAL::collinear(corner(mesh, triangle[0]), corner(mesh, triangle[1]), corner(mesh, triangle[2]));
  };
  std::vector<std::size_t> tested; // the moved triangles that are not degenerate
  std::vector<BoundingBox> testedBoxes;
  for (std::size_t t : movedTriangles)
  {
    if (isDegenerate(t))
    {
      pairs.emplace_back(t, t);
      continue;
    }
    tested.push_back(t);
    testedBoxes.push_back(boxOfTriangle(mesh, t));
  }
  if (!tested.empty())
  {
    // Every triangle whose box meets a moved one's, from one pass over the triangles.
    const TrianglesMeeting meeting = trianglesMeetingBoxes(mesh, testedBoxes, threads);
    std::vector<std::pair<std::size_t, std::size_t>> candidates;
    for (std::size_t i = 0; i < tested.size(); ++i)
      for (std::size_t k = meeting.start[i]; k < meeting.start[i + 1]; ++k)
      {
        const std::size_t other = meeting.triangles[k];
        if (other != tested[i])
          candidates.emplace_back(std::min(tested[i], other), std::max(tested[i], other));
      }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<char> crosses(candidates.size(), 0);
    parallelForRanges(candidates.size(), threads,
                      [&](std::size_t first, std::size_t last)
                      {
                        for (std::size_t i = first; i < last; ++i)
                          crosses[i] = !isDegenerate(candidates[i].first) && !isDegenerate(candidates[i].second) &&
                                       crossing(cornersOf(mesh, candidates[i].first), cornersOf(mesh, candidates[i].second));
                      });
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (crosses[i])
        pairs.push_back(candidates[i]);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace slicemesh

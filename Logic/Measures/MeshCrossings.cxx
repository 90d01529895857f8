#include "Measures/MeshCrossings.h"

#include "Core/BoundingBox.h"
#include "Core/MeetingBoxes.h"
#include "Core/ParallelFor.h"
#include "Core/SpatialHash.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace slicemesh
{
namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/** A box tagged with its mesh and, for a triangle's box, the triangle. */
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::pair<std::size_t, std::size_t>>;

/** `box` tagged with its mesh and triangle. */
Box tagged(BoundingBox box, std::size_t meshIndex, std::size_t t) // by value: CGAL takes non-const arrays
{
  return Box(box.low.data(), box.high.data(), { meshIndex, t });
}

Kernel::Triangle_3 triangle(const TriangleMesh& mesh, std::size_t t)
{
  auto point = [&](int corner)
  {
    const Point3& p = mesh.points[static_cast<std::size_t>(mesh.triangles[t][corner])];
    return Kernel::Point_3(p.x, p.y, p.z);
  };
  return { point(0), point(1), point(2) };
}

/** Meshes of this many triangles are searched one at a time, each on every thread. */
constexpr std::size_t largeMesh = 1 << 16;

/** A box over more cells than this is tested by every triangle instead of being filed. */
constexpr std::size_t mostCellsFiled = 64;

/** For each of `boxes`, the triangles of `mesh` whose boxes share a point with it, in increasing
 *  order. The boxes are filed under the cells of space they cover (cells as wide as all but the
 *  widest tenth of them, or two triangles); one pass over the triangles, in ranges on up to
 *  `threads` threads, looks up the cells each triangle's box covers. Linear in the triangles: a
 *  box intersection of a piece of a million triangles with the boxes of the specks around it
 *  sorted the million each time, on one thread. */
std::vector<std::vector<std::size_t>> trianglesMeeting(const TriangleMesh& mesh, const std::vector<BoundingBox>& boxes,
                                                       unsigned int threads)
{
  auto widthOf = [](const BoundingBox& box)
  { return std::max({ box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2] }); };
  std::vector<double> widths;
  for (const BoundingBox& box : boxes)
    widths.push_back(widthOf(box));
  const std::size_t tenth = widths.size() - 1 - (widths.size() - 1) / 10;
  std::nth_element(widths.begin(), widths.begin() + static_cast<std::ptrdiff_t>(tenth), widths.end());
  double triangleWidth = 0.0; // of a sample of the triangles, spread over the mesh
  const std::size_t stride = std::max<std::size_t>(1, mesh.triangles.size() / 1024);
  std::size_t sampled = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += stride, ++sampled)
    triangleWidth += widthOf(boxOfTriangle(mesh, t));
  triangleWidth /= static_cast<double>(std::max<std::size_t>(1, sampled));
  const double cellSize = std::max({ widths[tenth], 2.0 * triangleWidth, 1e-9 });
  SpatialHash filed(cellSize);
  std::vector<std::uint32_t> unfiled; // boxes over more than mostCellsFiled cells
  auto cellCount = [](const SpatialHash::CellRange& r)
  {
    return static_cast<double>(r.x1 - r.x0 + 1) * static_cast<double>(r.y1 - r.y0 + 1) *
           static_cast<double>(r.z1 - r.z0 + 1);
  };
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    const SpatialHash::CellRange cells = filed.cellsOf(boxes[b]);
    if (cellCount(cells) > static_cast<double>(mostCellsFiled))
      unfiled.push_back(static_cast<std::uint32_t>(b));
    else
      filed.insert(cells, static_cast<int>(b));
  }
  using Hit = std::pair<std::uint32_t, std::size_t>; // (box, triangle)
  const auto hitsByRange = fixedRangeResults<std::vector<Hit>>(
    mesh.triangles.size(), 1 << 14, threads,
    [&](std::vector<Hit>& hits, std::size_t first, std::size_t last)
    {
      std::vector<std::uint32_t> met;
      for (std::size_t t = first; t < last; ++t)
      {
        const BoundingBox box = boxOfTriangle(mesh, t);
        met.clear();
        auto test = [&](std::uint32_t b)
        {
          if (boxes[b].overlaps(box))
            met.push_back(b);
        };
        const SpatialHash::CellRange cells = filed.cellsOf(box);
        if (cellCount(cells) > static_cast<double>(mostCellsFiled)) // a triangle wider than the cells
          for (std::uint32_t b = 0; b < boxes.size(); ++b)
            test(b);
        else
        {
          filed.forEachIn(cells, [&](int b) { test(static_cast<std::uint32_t>(b)); });
          for (std::uint32_t b : unfiled)
            test(b);
        }
        std::sort(met.begin(), met.end());
        met.erase(std::unique(met.begin(), met.end()), met.end());
        for (std::uint32_t b : met)
          hits.emplace_back(b, t);
      }
    });
  std::vector<std::vector<std::size_t>> meeting(boxes.size());
  for (const std::vector<Hit>& hits : hitsByRange)
    for (const auto& [b, t] : hits)
      meeting[b].push_back(t);
  return meeting;
}

} // namespace

std::vector<TrianglePair> crossingTriangles(const std::vector<const TriangleMesh*>& meshes, unsigned int threads)
{
  // Pairs of meshes whose bounding boxes overlap: only their triangles can meet, and only within
  // the overlap of the two boxes.
  // (A mesh without triangles has an empty box, which meets none.)
  std::vector<BoundingBox> boxOfMesh(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m)
    boxOfMesh[m] = boxOfTriangles(*meshes[m]);
  const std::vector<std::pair<std::size_t, std::size_t>> meshPairs = meetingBoxes(boxOfMesh);
  // For each mesh, its triangles within each partner's box, from one pass over its triangles
  // (trianglesMeeting): a mesh whose box holds a thousand others (a brain's outer surface around
  // the specks of a thresholded MRI) was scanned whole once per partner.
  // Within a partner's box is within the overlap of the two boxes: a triangle's box lies in its own
  // mesh's box.
  std::vector<std::vector<std::pair<std::size_t, int>>> partnersOf(meshes.size()); // (pair, side)
  for (std::size_t pair = 0; pair < meshPairs.size(); ++pair)
  {
    partnersOf[meshPairs[pair].first].emplace_back(pair, 0);
    partnersOf[meshPairs[pair].second].emplace_back(pair, 1);
  }
  std::vector<std::array<std::vector<Box>, 2>> within(meshPairs.size()); // each pair's triangles of each side
  auto findWithin = [&](std::size_t m, unsigned int meshThreads)
  {
    std::vector<BoundingBox> partners;
    for (const auto& [pair, side] : partnersOf[m])
      partners.push_back(boxOfMesh[side == 0 ? meshPairs[pair].second : meshPairs[pair].first]);
    const std::vector<std::vector<std::size_t>> meeting = trianglesMeeting(*meshes[m], partners, meshThreads);
    for (std::size_t i = 0; i < partners.size(); ++i)
    {
      const auto [pair, side] = partnersOf[m][i];
      std::vector<Box>& list = within[pair][static_cast<std::size_t>(side)];
      for (std::size_t t : meeting[i])
        list.push_back(tagged(boxOfTriangle(*meshes[m], t), m, t));
    }
  };
  // Large meshes one after another on every thread, the others side by side.
  std::vector<std::size_t> large, small;
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (!partnersOf[m].empty())
      (meshes[m]->triangles.size() >= largeMesh ? large : small).push_back(m);
  for (std::size_t m : large)
    findWithin(m, threads);
  parallelFor(small.size(), threads, [&](std::size_t k) { findWithin(small[k], 1); });
  // Pair by pair, side by side: the triangles of each mesh within the other's box, against each
  // other (CGAL's box intersection), then the exact triangle test. Pairs within one mesh never come
  // up, where the box intersection of all triangles together went through every pair of
  // neighbouring triangles of every mesh only to pass them over.
  std::vector<std::vector<TrianglePair>> crossingByPair(meshPairs.size());
  parallelFor(meshPairs.size(), threads,
              [&](std::size_t pair)
              {
                std::vector<Box>& inA = within[pair][0];
                std::vector<Box>& inB = within[pair][1];
                std::vector<TrianglePair>& crossing = crossingByPair[pair];
                CGAL::box_intersection_d(inA.begin(), inA.end(), inB.begin(), inB.end(),
                                         [&](const Box& x, const Box& y)
                                         {
                                           const MeshTriangle tx{ x.info().first, x.info().second };
                                           const MeshTriangle ty{ y.info().first, y.info().second };
                                           if (CGAL::do_intersect(triangle(*meshes[tx.mesh], tx.triangle),
                                                                  triangle(*meshes[ty.mesh], ty.triangle)))
                                             crossing.push_back(tx.mesh < ty.mesh ? TrianglePair{ tx, ty }
                                                                                  : TrianglePair{ ty, tx });
                                         });
                inA = std::vector<Box>(); // not held beside the other pairs'
                inB = std::vector<Box>();
              });
  std::vector<TrianglePair> crossing;
  for (const std::vector<TrianglePair>& pairs : crossingByPair)
    crossing.insert(crossing.end(), pairs.begin(), pairs.end());
  // The box intersection reports pairs in an order of its own: sorted, the caller's result does
  // not depend on it.
  std::sort(crossing.begin(), crossing.end());
  return crossing;
}

} // namespace slicemesh

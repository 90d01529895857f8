#include "Measures/MeshCrossings.h"

#include "Core/BoundingBox.h"
#include "Core/MeetingBoxes.h"
#include "Core/ParallelFor.h"
#include "Measures/TrianglesMeetingBoxes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

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

/** Pairs of meshes with this many triangles within each other's boxes are searched in slabs across x,
 *  side by side. */
constexpr std::size_t largePair = 1 << 16;

const Box& boxOf(const Box& box)
{
  return box;
}

const Box& boxOf(const Box* box)
{
  return *box;
}

/** The triangles of `inA` (of one mesh) that cross triangles of `inB` (of another), added to
 *  `crossing`: CGAL's box intersection, then the exact triangle test, for the pairs `report` takes.
 *  The boxes are held by value or by pointer (`Handle`). */
template <typename Handle, typename Report>
void addCrossings(const std::vector<const TriangleMesh*>& meshes, std::vector<Handle>& inA, std::vector<Handle>& inB,
                  Report&& report, std::vector<TrianglePair>& crossing)
{
  CGAL::box_intersection_d(inA.begin(), inA.end(), inB.begin(), inB.end(),
                           [&](const Handle& handleX, const Handle& handleY)
                           {
                             const Box& x = boxOf(handleX);
                             const Box& y = boxOf(handleY);
                             if (!report(x, y))
                               return;
                             const MeshTriangle tx{ x.info().first, x.info().second };
                             const MeshTriangle ty{ y.info().first, y.info().second };
                             if (CGAL::do_intersect(triangle(*meshes[tx.mesh], tx.triangle),
                                                    triangle(*meshes[ty.mesh], ty.triangle)))
                               crossing.push_back(tx.mesh < ty.mesh ? TrianglePair{ tx, ty } : TrianglePair{ ty, tx });
                           });
}

/** addCrossings for a large pair, in slabs across x on every thread: each box goes to every slab it
 *  reaches, and a pair of boxes is taken only in the slab of the low x of their overlap, where both
 *  are. The body and the skin of a whole-body segmentation lie within each other's boxes whole, and
 *  their pair alone was searched on one thread while the others waited. */
void addCrossingsInSlabs(const std::vector<const TriangleMesh*>& meshes, std::vector<Box>& inA, std::vector<Box>& inB,
                         unsigned int threads, std::vector<TrianglePair>& crossing)
{
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const std::vector<Box>* boxes : { &inA, &inB })
    for (const Box& box : *boxes)
    {
      low = std::min(low, box.min_coord(0));
      high = std::max(high, box.max_coord(0));
    }
  const std::size_t slabs = 4 * static_cast<std::size_t>(threadCount(threads));
  const double width = (high - low) / static_cast<double>(slabs);
  // Coordinates near the largest double (an extent that overflows) or an extent of a few subnormals
  // give no usable width: the whole search.
  if (!(std::isfinite(low) && std::isfinite(high) && std::isfinite(width) && width > 0.0))
  {
    addCrossings(meshes, inA, inB, [](const Box&, const Box&) { return true; }, crossing);
    return;
  }
  auto slabOf = [&](double x) // x within [low, high]: a finite quotient
  {
    const double s = std::floor((x - low) / width);
    return static_cast<std::size_t>(std::clamp(s, 0.0, static_cast<double>(slabs - 1)));
  };
  // Pointers to the boxes: copies of a large pair's boxes were as much memory again.
  std::vector<std::array<std::vector<const Box*>, 2>> inSlab(slabs);
  for (int side = 0; side < 2; ++side)
    for (const Box& box : side == 0 ? inA : inB)
      for (std::size_t s = slabOf(box.min_coord(0)); s <= slabOf(box.max_coord(0)); ++s)
        inSlab[s][static_cast<std::size_t>(side)].push_back(&box);
  std::vector<std::vector<TrianglePair>> crossingInSlab(slabs);
  parallelFor(slabs, threads,
              [&](std::size_t s)
              {
                addCrossings(meshes, inSlab[s][0], inSlab[s][1],
                             [&](const Box& x, const Box& y)
                             { return slabOf(std::max(x.min_coord(0), y.min_coord(0))) == s; },
                             crossingInSlab[s]);
                inSlab[s] = {};
              });
  for (const std::vector<TrianglePair>& pairs : crossingInSlab)
    crossing.insert(crossing.end(), pairs.begin(), pairs.end());
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
  // (trianglesMeetingBoxes): a mesh whose box holds a thousand others (a brain's outer surface around
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
    const TrianglesMeeting meeting = trianglesMeetingBoxes(*meshes[m], partners, meshThreads);
    for (std::size_t i = 0; i < partners.size(); ++i)
    {
      const auto [pair, side] = partnersOf[m][i];
      std::vector<Box>& list = within[pair][static_cast<std::size_t>(side)];
      for (std::size_t k = meeting.start[i]; k < meeting.start[i + 1]; ++k)
        list.push_back(tagged(boxOfTriangle(*meshes[m], meeting.triangles[k]), m, meeting.triangles[k]));
    }
  };
  // Large meshes one after another on every thread, the others side by side.
  std::vector<std::size_t> withPartners;
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (!partnersOf[m].empty())
      withPartners.push_back(m);
  largeOnesFirst(withPartners, threads, [&](std::size_t m) { return meshes[m]->triangles.size() >= largeMesh; },
                 findWithin);
  // Pair by pair, side by side: the triangles of each mesh within the other's box, against each
  // other (CGAL's box intersection), then the exact triangle test; a large pair in slabs on every
  // thread first. Pairs within one mesh never come up, where the box intersection of all triangles
  // together went through every pair of neighbouring triangles of every mesh only to pass them over.
  std::vector<std::vector<TrianglePair>> crossingByPair(meshPairs.size());
  std::vector<std::size_t> allPairs(meshPairs.size());
  std::iota(allPairs.begin(), allPairs.end(), 0);
  largeOnesFirst(allPairs, threads,
                 [&](std::size_t pair) { return within[pair][0].size() + within[pair][1].size() >= largePair; },
                 [&](std::size_t pair, unsigned int pairThreads)
                 {
                   std::vector<Box>& inA = within[pair][0];
                   std::vector<Box>& inB = within[pair][1];
                   if (threadCount(pairThreads) > 1)
                     addCrossingsInSlabs(meshes, inA, inB, pairThreads, crossingByPair[pair]);
                   else
                     addCrossings(meshes, inA, inB, [](const Box&, const Box&) { return true; }, crossingByPair[pair]);
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

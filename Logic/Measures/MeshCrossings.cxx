#include "Measures/MeshCrossings.h"

#include "Core/BoundingBox.h"
#include "Core/MeetingBoxes.h"
#include "Core/ParallelFor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>

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
  // For each mesh, its triangles within each partner's box, from one box intersection of its
  // triangles' boxes with its partners' boxes: a mesh whose box holds a thousand others (a brain's
  // outer surface around the specks of a thresholded MRI) was scanned whole once per partner.
  // Within a partner's box is within the overlap of the two boxes: a triangle's box lies in its own
  // mesh's box.
  std::vector<std::vector<std::pair<std::size_t, int>>> partnersOf(meshes.size()); // (pair, side)
  for (std::size_t pair = 0; pair < meshPairs.size(); ++pair)
  {
    partnersOf[meshPairs[pair].first].emplace_back(pair, 0);
    partnersOf[meshPairs[pair].second].emplace_back(pair, 1);
  }
  std::vector<std::array<std::vector<Box>, 2>> within(meshPairs.size()); // each pair's triangles of each side
  parallelFor(meshes.size(), threads,
              [&](std::size_t m)
              {
                if (partnersOf[m].empty())
                  return;
                std::vector<Box> triangles(meshes[m]->triangles.size());
                for (std::size_t t = 0; t < triangles.size(); ++t)
                  triangles[t] = tagged(boxOfTriangle(*meshes[m], t), m, t);
                std::vector<Box> partners;
                for (std::size_t i = 0; i < partnersOf[m].size(); ++i)
                {
                  const auto [pair, side] = partnersOf[m][i];
                  const std::size_t other = side == 0 ? meshPairs[pair].second : meshPairs[pair].first;
                  partners.push_back(tagged(boxOfMesh[other], other, i));
                }
                CGAL::box_intersection_d(triangles.begin(), triangles.end(), partners.begin(), partners.end(),
                                         [&](const Box& triangle, const Box& partner)
                                         {
                                           const auto [pair, side] = partnersOf[m][partner.info().second];
                                           within[pair][static_cast<std::size_t>(side)].push_back(triangle);
                                         });
              });
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

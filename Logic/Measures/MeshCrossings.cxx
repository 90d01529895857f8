#include "Measures/MeshCrossings.h"

#include "Core/BoundingBox.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>

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

std::vector<TrianglePair> crossingTriangles(const std::vector<const TriangleMesh*>& meshes)
{
  // Meshes whose bounding boxes overlap another's: only their triangles can meet.
  std::vector<Box> meshBoxes;
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    if (meshes[m]->triangles.empty())
      continue;
    meshBoxes.push_back(tagged(boxOfTriangles(*meshes[m]), m, 0));
  }
  std::vector<char> candidate(meshes.size(), 0);
  CGAL::box_self_intersection_d(meshBoxes.begin(), meshBoxes.end(),
                                [&](const Box& a, const Box& b)
                                { candidate[a.info().first] = candidate[b.info().first] = 1; });

  std::vector<Box> boxes;
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (candidate[m])
      for (std::size_t t = 0; t < meshes[m]->triangles.size(); ++t)
        boxes.push_back(tagged(boxOfTriangle(*meshes[m], t), m, t));
  std::vector<TrianglePair> crossing;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(),
                                [&](const Box& a, const Box& b)
                                {
                                  MeshTriangle ta{ a.info().first, a.info().second };
                                  MeshTriangle tb{ b.info().first, b.info().second };
                                  if (ta.mesh == tb.mesh)
                                    return; // within one mesh: its own validation's concern
                                  if (CGAL::do_intersect(triangle(*meshes[ta.mesh], ta.triangle),
                                                         triangle(*meshes[tb.mesh], tb.triangle)))
                                    crossing.push_back(ta.mesh < tb.mesh ? TrianglePair{ ta, tb } : TrianglePair{ tb, ta });
                                });
  // The box intersection reports pairs in an order of its own: sorted, the caller's result does
  // not depend on it.
  std::sort(crossing.begin(), crossing.end());
  return crossing;
}

} // namespace slicemesh

// CGAL's AABB tree over the triangles of a TriangleMesh itself, without the Surface_mesh copy that
// CGAL's face-graph primitive needs: on a large piece that copy is as large as the tree. Internal:
// CGAL stays out of the installed headers.
#ifndef TriangleMeshTree_h
#define TriangleMeshTree_h

#include "Measures/SurfaceMeshConversion.h"

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace slicemesh
{

/** Triangle t of the mesh, its corners in the triangle's order: what CGAL's face-graph primitive
 *  gives for the face a Surface_mesh makes of it (toSurfaceMesh), so that the tree, and every
 *  closest point found in it, is the same. */
struct TriangleOfMesh
{
  using key_type = std::uint32_t;
  using value_type = CgalKernel::Triangle_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const TriangleMesh* mesh = nullptr;

  friend value_type get(const TriangleOfMesh& map, key_type t)
  {
    const Triangle& triangle = map.mesh->triangles[t];
    const auto corner = [&](int c)
    {
      const Point3& p = map.mesh->points[static_cast<std::size_t>(triangle[c])];
      return CgalKernel::Point_3(p.x, p.y, p.z);
    };
    return value_type(corner(0), corner(1), corner(2));
  }
};

/** The first corner of triangle t: the face-graph primitive's reference point (where the tree's
 *  construction sorts it). */
struct FirstCornerOfMesh
{
  using key_type = std::uint32_t;
  using value_type = CgalKernel::Point_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const TriangleMesh* mesh = nullptr;

  friend value_type get(const FirstCornerOfMesh& map, key_type t)
  {
    const Point3& p = map.mesh->points[static_cast<std::size_t>(map.mesh->triangles[t][0])];
    return value_type(p.x, p.y, p.z);
  }
};

/** A primitive is the triangle's index (4 bytes); the mesh is the tree's shared data. */
using TriangleMeshPrimitive =
  CGAL::AABB_primitive<std::uint32_t, TriangleOfMesh, FirstCornerOfMesh, CGAL::Tag_true, CGAL::Tag_false>;
using TriangleMeshTree = CGAL::AABB_tree<CGAL::AABB_traits<CgalKernel, TriangleMeshPrimitive>>;

/** CGAL's closest-point search (its Projection_traits) with one step more: a triangle whose box lies
 *  beyond the closest point found so far is passed over, where CGAL computes the triangle's closest
 *  point (most of a query's time) only to keep the one it had. Such a triangle cannot give a point as
 *  close, so the search keeps the same points in the same order and ends with the same one, bit for
 *  bit. The box is judged with a margin far above rounding, on the side of computing; only for a
 *  triangle a billionth of its length thin, whose projected point CGAL's own rounding can carry
 *  outside its box, could the two differ (such a triangle is no part of a valid tiling's shape). */
class ClosestPointSearch
{
public:
  using Traits = TriangleMeshTree::AABB_traits;
  using Point = CgalKernel::Point_3;

  ClosestPointSearch(const Traits& traits, const Point& query, const Point& hint)
    : m_Traits(traits)
    , m_Margin(1e-9 * (1.0 + std::max({ std::abs(query.x()), std::abs(query.y()), std::abs(query.z()) })))
    , m_Closest(hint)
  {
    setReach(query);
  }

  bool go_further() const { return true; }

  void intersection(const Point& query, const TriangleMeshPrimitive& primitive)
  {
    const CgalKernel::Triangle_3 triangle = CGAL::internal::Primitive_helper<Traits>::get_datum(primitive, m_Traits);
    double boxDistance = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double a = triangle[0][axis], b = triangle[1][axis], c = triangle[2][axis], q = query[axis];
      const double below = std::min({ a, b, c }) - q, above = q - std::max({ a, b, c });
      const double outside = std::max({ below, above, 0.0 });
      boxDistance += outside * outside;
    }
    if (boxDistance > m_Reach)
      return;
    const Point closest = m_Traits.closest_point_object()(query, primitive, m_Closest);
    if (!m_Traits.equal_3_object()(closest, m_Closest))
    {
      m_Closest = closest;
      setReach(query);
    }
  }

  bool do_intersect(const Point& query, const CGAL::AABB_node<Traits>& node) const
  {
    return m_Traits.compare_distance_object()(query, node.bbox(), m_Closest) == CGAL::SMALLER;
  }

  const Point& closest() const { return m_Closest; }

private:
  /** The squared distance beyond which a box is passed over: the closest point's, plus the margin. */
  void setReach(const Point& query)
  {
    const double reach = std::sqrt(CGAL::squared_distance(query, m_Closest)) + m_Margin;
    m_Reach = reach * reach;
  }

  const Traits& m_Traits;
  double m_Margin;
  Point m_Closest;
  double m_Reach = 0.0;
};

/** tree.closest_point(query, hint), sooner (ClosestPointSearch). */
inline CgalKernel::Point_3 closestPoint(const TriangleMeshTree& tree, const CgalKernel::Point_3& query,
                                        const CgalKernel::Point_3& hint)
{
  ClosestPointSearch search(tree.traits(), query, hint);
  tree.traversal(query, search);
  return search.closest();
}

/** Fills the empty `tree` with the mesh's triangles in their order (the mesh must outlive it). */
inline void insertTriangles(TriangleMeshTree& tree, const TriangleMesh& mesh)
{
  tree.insert(boost::counting_iterator<std::uint32_t>(0),
              boost::counting_iterator<std::uint32_t>(static_cast<std::uint32_t>(mesh.triangles.size())),
              TriangleOfMesh{ &mesh }, FirstCornerOfMesh{ &mesh });
}

} // namespace slicemesh

#endif

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

/** Fills the empty `tree` with the mesh's triangles in their order (the mesh must outlive it). */
inline void insertTriangles(TriangleMeshTree& tree, const TriangleMesh& mesh)
{
  tree.insert(boost::counting_iterator<std::uint32_t>(0),
              boost::counting_iterator<std::uint32_t>(static_cast<std::uint32_t>(mesh.triangles.size())),
              TriangleOfMesh{ &mesh }, FirstCornerOfMesh{ &mesh });
}

} // namespace slicemesh

#endif

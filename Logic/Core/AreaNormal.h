// A triangle's area normal: the one cross product of its edges that the stages measure normals,
// areas and how a surface faces the grid with.
#ifndef AreaNormal_h
#define AreaNormal_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** (b - a) x (c - a): twice the area of triangle abc times its unit normal, which follows the
 *  winding a, b, c. */
inline Point3 areaNormal(const Point3& a, const Point3& b, const Point3& c)
{
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  return { uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx };
}

/** The area normal of triangle t of the mesh. */
inline Point3 areaNormal(const TriangleMesh& mesh, const Triangle& t)
{
  return areaNormal(mesh.points[static_cast<std::size_t>(t[0])], mesh.points[static_cast<std::size_t>(t[1])],
                    mesh.points[static_cast<std::size_t>(t[2])]);
}

} // namespace slicemesh

#endif

// Small hand-made meshes and measures shared by the mesh-module tests.
#ifndef TestMeshes_h
#define TestMeshes_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh::testing
{

/** The axis-aligned box [0,a] x [0,b] x [0,c], 8 vertices, 12 triangles, normals pointing out. */
inline TriangleMesh box(double a, double b, double c)
{
  TriangleMesh mesh;
  mesh.points = { { 0, 0, 0 }, { a, 0, 0 }, { a, b, 0 }, { 0, b, 0 },
                  { 0, 0, c }, { a, 0, c }, { a, b, c }, { 0, b, c } };
  mesh.triangles = { { 0, 2, 1 }, { 0, 3, 2 },   // bottom, seen from below
                     { 4, 5, 6 }, { 4, 6, 7 },   // top
                     { 0, 1, 5 }, { 0, 5, 4 },   // y = 0
                     { 1, 2, 6 }, { 1, 6, 5 },   // x = a
                     { 2, 3, 7 }, { 2, 7, 6 },   // y = b
                     { 3, 0, 4 }, { 3, 4, 7 } }; // x = 0
  return mesh;
}

/** Signed enclosed volume (divergence theorem): positive when the triangles wind outward. */
inline double signedVolume(const TriangleMesh& mesh)
{
  double sixTimesVolume = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3& p = mesh.points[t[0]];
    const Point3& q = mesh.points[t[1]];
    const Point3& r = mesh.points[t[2]];
    sixTimesVolume += p.x * (q.y * r.z - q.z * r.y) - p.y * (q.x * r.z - q.z * r.x) + p.z * (q.x * r.y - q.y * r.x);
  }
  return sixTimesVolume / 6.0;
}

} // namespace slicemesh::testing

#endif

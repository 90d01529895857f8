// A closed test surface and the queries the closest-point searches' tests ask of it.
#ifndef ClosestPointCases_h
#define ClosestPointCases_h

#include "Measures/SurfaceMeshConversion.h"

#include <cmath>
#include <random>

namespace slicemesh::testing
{

/** A sphere of latitude-longitude rings with a bumpy radius: triangles of many sizes and slopes. */
inline TriangleMesh bumpySphere(int rings, int sectors)
{
  TriangleMesh mesh;
  auto radius = [](double polar, double azimuth) { return 20.0 + 1.5 * std::sin(5.0 * polar) * std::cos(3.0 * azimuth); };
  mesh.points.push_back({ 0.0, 0.0, -radius(0.0, 0.0) });
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < sectors; ++s)
    {
      const double polar = M_PI * r / rings, azimuth = 2.0 * M_PI * s / sectors, rho = radius(polar, azimuth);
      mesh.points.push_back({ rho * std::sin(polar) * std::cos(azimuth), rho * std::sin(polar) * std::sin(azimuth),
                              -rho * std::cos(polar) });
    }
  mesh.points.push_back({ 0.0, 0.0, radius(M_PI, 0.0) });
  const auto top = static_cast<std::int32_t>(mesh.points.size() - 1);
  auto at = [sectors](int r, int s) { return static_cast<std::int32_t>(1 + (r - 1) * sectors + (s % sectors)); };
  for (int s = 0; s < sectors; ++s)
  {
    mesh.triangles.push_back({ 0, at(1, s + 1), at(1, s) });
    mesh.triangles.push_back({ top, at(rings - 1, s), at(rings - 1, s + 1) });
    for (int r = 1; r + 1 < rings; ++r)
    {
      mesh.triangles.push_back({ at(r, s), at(r, s + 1), at(r + 1, s + 1) });
      mesh.triangles.push_back({ at(r, s), at(r + 1, s + 1), at(r + 1, s) });
    }
  }
  return mesh;
}

/** Calls compare(query, hint) for points near the surface and far from it, with hints (points on it)
 *  near the answer and anywhere, and for points right on vertices and on the middle of edges, where
 *  several triangles are equally close. */
template <typename Compare>
void forEachClosestPointQuery(const TriangleMesh& mesh, Compare&& compare)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> anyPoint(0, mesh.points.size() - 1);
  for (int n = 0; n < 4000; ++n)
  {
    // A vertex of the mesh (on the surface: a valid hint), and a point moved off it by up to 0.05
    // to 5 mm: the remesh's queries are a fraction of an edge from their hint.
    const Point3& v = mesh.points[anyPoint(random)];
    const double reach = n % 4 == 0 ? 5.0 : n % 4 == 1 ? 1.0 : n % 4 == 2 ? 0.3 : 0.05;
    const CgalKernel::Point_3 query(v.x + reach * unit(random), v.y + reach * unit(random), v.z + reach * unit(random));
    compare(query, CgalKernel::Point_3(v.x, v.y, v.z));
    // A hint anywhere on the surface, most often far from the answer.
    const Point3& far = mesh.points[anyPoint(random)];
    compare(query, CgalKernel::Point_3(far.x, far.y, far.z));
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 7)
  {
    const Point3& a = mesh.points[static_cast<std::size_t>(mesh.triangles[t][0])];
    const Point3& b = mesh.points[static_cast<std::size_t>(mesh.triangles[t][1])];
    compare(CgalKernel::Point_3(a.x, a.y, a.z), CgalKernel::Point_3(b.x, b.y, b.z));
    compare(CgalKernel::Point_3(0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)), CgalKernel::Point_3(a.x, a.y, a.z));
  }
}

} // namespace slicemesh::testing

#endif

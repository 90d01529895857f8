// Which points a closed surface encloses, decided exactly, also where the ray meets an edge or a
// vertex and for points on the surface itself.
#include "ContourStacks.h"
#include "Measures/PointsInside.h"
#include "Measures/SurfaceMeshConversion.h"
#include "Tiling/SurfaceReconstruction.h"

#include <CGAL/Side_of_triangle_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slicemesh::testing
{
namespace
{

/** The box [low, high]^3 as 12 triangles facing out (inward if `inward`): every face split along a
 *  diagonal, so rays from a grid of points meet vertices, edges and diagonals. */
TriangleMesh cube(double low, double high, bool inward = false)
{
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.points.push_back({ k & 1 ? high : low, k & 2 ? high : low, k & 4 ? high : low });
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                            { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& f : faces)
    for (const Triangle& t : { Triangle{ f[0], f[1], f[2] }, Triangle{ f[0], f[2], f[3] } })
      mesh.triangles.push_back(inward ? Triangle{ t[0], t[2], t[1] } : t);
  return mesh;
}

TEST(PointsInside, RaysThroughVerticesEdgesAndFacesOfABoxAreDecidedExactly)
{
  // The point moved by (e, e^2, e^3) is inside the closed box exactly when the point is in the
  // half-open box [0, 1)^3: points on the faces x, y, z = 0 are inside, on x, y, z = 1 outside.
  const std::vector<double> at{ -0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5 };
  std::vector<Point3> points;
  for (double x : at)
    for (double y : at)
      for (double z : at)
        points.push_back({ x, y, z });
  auto halfOpen = [](double v) { return v >= 0.0 && v < 1.0; };
  for (unsigned int threads : { 1u, 2u })
  {
    const std::vector<char> inside = pointsInside(cube(0.0, 1.0), points, threads);
    ASSERT_EQ(inside.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const Point3& p = points[i];
      EXPECT_EQ(inside[i] != 0, halfOpen(p.x) && halfOpen(p.y) && halfOpen(p.z))
        << p.x << " " << p.y << " " << p.z << " on " << threads << " threads";
    }
  }
}

TEST(PointsInside, APointInACavityIsOutside)
{
  TriangleMesh hollow = cube(0.0, 4.0);
  const TriangleMesh cavity = cube(1.0, 3.0, true);
  const auto offset = static_cast<std::int32_t>(hollow.points.size());
  hollow.points.insert(hollow.points.end(), cavity.points.begin(), cavity.points.end());
  for (Triangle t : cavity.triangles)
    hollow.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  // In the wall, in the cavity (on the rays through the cavity's corners and diagonals), outside.
  const std::vector<char> inside =
    pointsInside(hollow, { { 0.5, 0.5, 0.5 }, { 2.0, 2.0, 2.0 }, { 1.0, 1.0, 0.5 }, { 1.0, 1.0, 2.0 }, { 2.0, 2.0, 3.5 }, { 5.0, 2.0, 2.0 } });
  EXPECT_EQ(inside, (std::vector<char>{ 1, 0, 1, 0, 1, 0 }));
}

TEST(PointsInside, AgreesWithCgalsInsideTestOnATiledBall)
{
  // A tiled ball of radius 10, with points straight above and below its vertices among random ones,
  // so that many rays pass through vertices: the answers agree with CGAL's Side_of_triangle_mesh
  // (which shoots again when a ray grazes) and, away from the surface, with the sphere.
  const ContourStack stack = sliceStack(-9.5, 9.5, 1.0, [](double z)
                                        { return std::vector<Polygon2>{ circle(0.0, 0.0, std::sqrt(100.0 - z * z), 40) }; });
  const TriangleMesh ball = reconstructSurface(stack);
  std::vector<Point3> points;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-11.0, 11.0);
  for (int k = 0; k < 3000; ++k)
    points.push_back({ coordinate(random), coordinate(random), coordinate(random) });
  for (std::size_t k = 0; k < ball.points.size(); k += 7) // below and above vertices
    for (double dz : { -30.0, 0.3, 30.0 })
      points.push_back({ ball.points[k].x, ball.points[k].y, ball.points[k].z + dz });
  CgalSurfaceMesh surface;
  toSurfaceMesh(ball, surface);
  const CGAL::Side_of_triangle_mesh<CgalSurfaceMesh, CgalKernel> side(surface);
  const std::vector<char> inside = pointsInside(ball, points, 2);
  std::size_t insideCount = 0, farChecked = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Point3& p = points[i];
    const CGAL::Bounded_side cgal = side(CgalKernel::Point_3(p.x, p.y, p.z));
    if (cgal != CGAL::ON_BOUNDARY)
      EXPECT_EQ(inside[i] != 0, cgal == CGAL::ON_BOUNDED_SIDE) << p.x << " " << p.y << " " << p.z;
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (std::abs(r - 10.0) > 1.0)
    {
      EXPECT_EQ(inside[i] != 0, r < 10.0) << r;
      ++farChecked;
    }
    insideCount += inside[i];
  }
  EXPECT_GT(farChecked, 2000u);
  EXPECT_GT(insideCount, 300u);
}

} // namespace
} // namespace slicemesh::testing

#include "Finishing/CrossingPlaces.h"

#include "Core/SpatialHash.h"

namespace slicemesh
{

Point3 centroid(const TriangleMesh& mesh, std::size_t t)
{
  const Point3& a = mesh.points[static_cast<std::size_t>(mesh.triangles[t][0])];
  const Point3& b = mesh.points[static_cast<std::size_t>(mesh.triangles[t][1])];
  const Point3& c = mesh.points[static_cast<std::size_t>(mesh.triangles[t][2])];
  return { (a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0, (a.z + b.z + c.z) / 3.0 };
}

std::vector<Point3> crossingPlaces(const TriangleMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  std::vector<Point3> places;
  for (const auto& [first, second] : crossings)
    for (std::size_t t : { first, second })
      places.push_back(centroid(mesh, t));
  return places;
}

double keptRadius(const SurfaceFinishingOptions& options)
{
  return options.remeshing.targetEdgeLength;
}

std::vector<char> verticesNear(const TriangleMesh& mesh, const std::vector<Point3>& points, double radius)
{
  SpatialHash columns(radius);
  for (std::size_t i = 0; i < points.size(); ++i)
    columns.insert(Point2{ points[i].x, points[i].y }, static_cast<int>(i));
  std::vector<char> near(mesh.points.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    const Point3& q = mesh.points[v];
    near[v] = columns.anyIn(columns.cellsWithin(Point2{ q.x, q.y }, radius),
                            [&](int i)
                            {
                              const Point3& p = points[static_cast<std::size_t>(i)];
                              const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
                              return dx * dx + dy * dy + dz * dz <= radius * radius;
                            });
  }
  return near;
}

std::vector<char> trianglesNear(const TriangleMesh& mesh, const std::vector<Point3>& points, double radius)
{
  const std::vector<char> near = verticesNear(mesh, points, radius);
  std::vector<char> flagged(mesh.triangles.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::int32_t v : mesh.triangles[t])
      flagged[t] = flagged[t] || near[static_cast<std::size_t>(v)];
  return flagged;
}

} // namespace slicemesh

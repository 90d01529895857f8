#include "PlannerContours.h"

#include "Contours/MarchingSquares.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{
namespace
{

/** Sampling of the signed distance within a slice: the outline found on it lies within a few
 *  micrometres of the true one, far below any point spacing measured. */
constexpr double outlineCell = 0.1;

/** Points at irregular steps along the closed polyline `outline`, about `spacing` apart on average. */
std::vector<Point3> planningContour(const Polygon2& outline, double z, double spacing, std::mt19937& random)
{
  std::vector<double> along(outline.size() + 1, 0.0);
  for (std::size_t i = 0; i < outline.size(); ++i)
    along[i + 1] = along[i] + distance(outline[i], outline[(i + 1) % outline.size()]);
  const double length = along.back();
  const int points = std::max(8, static_cast<int>(std::lround(length / spacing)));
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  std::vector<Point3> contour;
  std::size_t segment = 0;
  for (int k = 0; k < points; ++k)
  {
    const double at = length * (k + (k == 0 ? 0.0 : jitter(random))) / points;
    while (segment + 1 < outline.size() && along[segment + 1] < at)
      ++segment;
    const Point2& a = outline[segment];
    const Point2& b = outline[(segment + 1) % outline.size()];
    const double span = along[segment + 1] - along[segment];
    const double t = span > 0.0 ? (at - along[segment]) / span : 0.0;
    contour.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), z });
  }
  return contour;
}

} // namespace

std::vector<std::vector<Point3>> plannerContours(const Phantom& phantom, double sliceSpacing, double pointSpacing,
                                                 std::mt19937& random)
{
  std::vector<std::vector<Point3>> contours;
  const Bounds bounds = phantom.bounds();
  const Box2 box{ bounds.lower.x() - 1.0, bounds.lower.y() - 1.0, bounds.upper.x() + 1.0, bounds.upper.y() + 1.0 };
  for (double z = bounds.lower.z() + 0.37 * sliceSpacing; z < bounds.upper.z(); z += sliceSpacing)
  {
    const ScalarGrid2 grid = sampleGrid(box, outlineCell,
                                        [&](const std::vector<Point2>& nodes, std::vector<double>& values)
                                        {
                                          for (const Point2& p : nodes)
                                            values.push_back(phantom.signedDistance(Vector3(p.x, p.y, z)));
                                        });
    for (const Polygon2& outline : zeroContours(grid, 4.0 * outlineCell * outlineCell))
      contours.push_back(planningContour(outline, z, pointSpacing, random));
  }
  return contours;
}

} // namespace slicemesh

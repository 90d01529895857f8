#include "Finishing/PieceTargetVolumes.h"

#include "Core/SpatialHash.h"

#include <cmath>
#include <limits>
#include <map>

namespace slicemesh
{
namespace
{

/** The vertices of one height, in the plane, with their pieces. */
struct Level
{
  explicit Level(double cellSize)
    : grid(cellSize)
  {
  }
  SpatialHash grid;
  std::vector<Point2> points;
  std::vector<std::size_t> piece;
};

} // namespace

std::vector<double> pieceTargetVolumes(const std::vector<const TriangleMesh*>& pieces,
                                       const std::vector<ContourVolume>& shares, double total)
{
  std::vector<double> targets(pieces.size(), 0.0);
  double sum = 0.0;
  for (const ContourVolume& share : shares)
    sum += share.volume;
  if (!(sum > 0.0))
    return targets;
  // Only the heights of the shares are indexed; a cell of about a millimetre holds a few points of a
  // contour, and the search widens until it finds one.
  constexpr double cellSize = 1.0;
  std::map<double, Level> levels;
  for (const ContourVolume& share : shares)
    levels.try_emplace(share.point.z, cellSize);
  double extent = cellSize;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (const Point3& v : pieces[p]->points)
    {
      const auto level = levels.find(v.z);
      if (level == levels.end())
        continue;
      level->second.grid.insert(Point2{ v.x, v.y }, static_cast<int>(level->second.points.size()));
      level->second.points.push_back({ v.x, v.y });
      level->second.piece.push_back(p);
      extent = std::max({ extent, std::abs(v.x), std::abs(v.y) });
    }
  for (const ContourVolume& share : shares)
  {
    const Level& level = levels.at(share.point.z);
    if (level.points.empty())
      continue;
    const Point2 at{ share.point.x, share.point.y };
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    // Every point within `radius` is in the cells searched: once the nearest found is that close, it is the nearest.
    for (double radius = cellSize; nearest < 0 || std::sqrt(best) > radius; radius *= 2.0)
    {
      level.grid.forEachIn(level.grid.cellsWithin(at, radius),
                           [&](int i)
                           {
                             const Point2& q = level.points[static_cast<std::size_t>(i)];
                             const double d = (q.x - at.x) * (q.x - at.x) + (q.y - at.y) * (q.y - at.y);
                             if (d < best || (d == best && i < nearest))
                               best = d, nearest = i;
                           });
      if (radius > 4.0 * (extent + std::abs(at.x) + std::abs(at.y)))
        break;
    }
    if (nearest >= 0)
      targets[level.piece[static_cast<std::size_t>(nearest)]] += share.volume;
  }
  for (double& target : targets)
    target *= total / sum;
  return targets;
}

} // namespace slicemesh

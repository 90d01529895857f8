#include "Sections/ContourConstraints.h"

#include "Contours/ContourNesting.h"
#include "Core/ArcLengthWalk.h"
#include "Core/PlanarGeometry.h"
#include "Correspondence/PolygonProximity.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace slicemesh
{

namespace
{

/** count points at equal arc-length steps along the closed polygon, starting at its first vertex. */
std::vector<Point2> resampleEvenly(const Polygon2& polygon, std::size_t count)
{
  const double step = perimeter(polygon) / static_cast<double>(count);
  std::vector<Point2> samples;
  samples.reserve(count);
  // A running sum of the step (the contour resampling multiplies it: their last bits differ); a
  // target past the end by rounding gives no sample.
  ArcLengthWalk walk(polygon);
  for (double target = 0.0; samples.size() < count && walk.reach(target); target += step)
    samples.push_back(walk.at(target));
  return samples;
}

/** Whether p lies in the solid of a slice: inside an odd number of its contours. */
bool inSolid(const std::vector<IndexedPolygon>& contours, const Point2& p, bool& onBoundary)
{
  int count = 0;
  onBoundary = false;
  for (const IndexedPolygon& c : contours)
  {
    const IndexedPolygon::Location where = c.locate(p);
    onBoundary = onBoundary || where == IndexedPolygon::Location::Boundary;
    count += where == IndexedPolygon::Location::Inside ? 1 : 0;
  }
  return count % 2 == 1;
}

} // namespace

std::vector<ImplicitConstraint> contourConstraints(const std::vector<Slice>& slices, const ConstraintSampling& sampling,
                                                   ConstraintSummary* summaryOut)
{
  ConstraintSummary summary;
  // Orient copies so that the solid lies to the left of every contour.
  std::vector<std::vector<Polygon2>> oriented(slices.size());
  double totalLength = 0.0;
  std::size_t contourCount = 0;
  for (std::size_t s = 0; s < slices.size(); ++s)
  {
    for (const Polygon2& c : slices[s].contours)
      if (c.size() >= 3)
        oriented[s].push_back(c);
    orientAndNest(oriented[s]);
    for (const Polygon2& c : oriented[s])
      totalLength += perimeter(c);
    contourCount += oriented[s].size();
  }
  std::vector<ImplicitConstraint> constraints;
  if (contourCount == 0 || !(totalLength > 0.0))
    return constraints;

  // Each sample costs three centres (on the contour, inside, outside).
  const double samplesInBudget = std::max(1.0, static_cast<double>(sampling.maxCentres) / 3.0);
  const double step = totalLength / samplesInBudget;
  // Many small contours (noise, a spray of specks) would each take the minimum, far over the budget,
  // and the dense solve grows with the cube of the centres: a 20 x 24 x 19 noise volume spent two
  // minutes in fits of thousands of centres. Under such pressure a contour gets three samples (the
  // fewest that outline it); a function over three times the budget is not fitted at all.
  std::size_t minimumSamples = std::max<std::size_t>(sampling.minSamplesPerContour, 3);
  if (static_cast<double>(contourCount * minimumSamples) > samplesInBudget)
    minimumSamples = 3;
  if (3 * 3 * contourCount > 3 * sampling.maxCentres)
    throw Error(std::to_string(contourCount) + " contours, more than an implicit function of " +
                std::to_string(3 * sampling.maxCentres) + " centres can take");
  summary.sampleSpacing = step;
  for (std::size_t s = 0; s < slices.size(); ++s)
  {
    std::vector<IndexedPolygon> indexed;
    indexed.reserve(oriented[s].size());
    for (const Polygon2& c : oriented[s])
      indexed.emplace_back(c);
    const double z = slices[s].z;
    for (const Polygon2& contour : oriented[s])
    {
      const double length = perimeter(contour);
      const std::size_t count = std::max<std::size_t>(minimumSamples, static_cast<std::size_t>(std::lround(length / step)));
      const std::vector<Point2> samples = resampleEvenly(contour, count);
      // Offset by a fraction of the local sample spacing (smaller on contours kept at the minimum count).
      const double localSpacing = std::min(step, length / static_cast<double>(count));
      const double delta = sampling.normalOffsetFraction * localSpacing;
      summary.normalOffset = std::max(summary.normalOffset, delta);
      const std::size_t m = samples.size();
      for (std::size_t i = 0; i < m; ++i)
      {
        const Point2& p = samples[i];
        constraints.push_back({ { p.x, p.y, z }, 0.0 });
        ++summary.onSurface;
        // Tangent by central difference of the neighbouring samples; outward normal on its right.
        const Point2& prev = samples[(i + m - 1) % m];
        const Point2& next = samples[(i + 1) % m];
        const double tx = next.x - prev.x, ty = next.y - prev.y;
        const double norm = std::hypot(tx, ty);
        if (!(norm > 0.0))
          continue;
        const double nx = ty / norm, ny = -tx / norm;
        for (const double side : { 1.0, -1.0 })
        {
          const Point2 q{ p.x + side * delta * nx, p.y + side * delta * ny };
          bool onBoundary = false;
          const bool solid = inSolid(indexed, q, onBoundary);
          if (onBoundary || solid != (side < 0.0))
          {
            ++summary.droppedOffSurface;
            continue;
          }
          constraints.push_back({ { q.x, q.y, z }, side * delta });
          ++summary.offSurface;
        }
      }
    }
  }
  if (summaryOut)
    *summaryOut = summary;
  return constraints;
}

} // namespace slicemesh

#include "Contours/ContourNesting.h"

#include "Core/MeetingBoxes.h"
#include "Core/PlanarGeometry.h"

#include <algorithm>

namespace slicemesh
{

Polygon2 cleanContour(const Polygon2& contour, double tolerance, bool dropArealess)
{
  Polygon2 cleaned;
  cleaned.reserve(contour.size());
  for (const Point2& p : contour)
  {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw Error("contour point is not finite");
    if (!cleaned.empty() && distance(cleaned.back(), p) <= tolerance)
      continue;
    // A spike a -> b -> a collapses to a.
    if (cleaned.size() >= 2 && distance(cleaned[cleaned.size() - 2], p) <= tolerance)
    {
      cleaned.pop_back();
      continue;
    }
    cleaned.push_back(p);
  }
  // The closing edge can produce the same two faults.
  bool changed = true;
  while (changed && cleaned.size() >= 3)
  {
    changed = false;
    if (distance(cleaned.front(), cleaned.back()) <= tolerance)
    {
      cleaned.pop_back();
      changed = true;
    }
    else if (distance(cleaned[cleaned.size() - 2], cleaned.front()) <= tolerance)
    {
      cleaned.pop_back();
      cleaned.erase(cleaned.begin());
      changed = true;
    }
    else if (distance(cleaned.back(), cleaned[1]) <= tolerance)
    {
      cleaned.erase(cleaned.begin());
      changed = true;
    }
  }
  if (cleaned.size() < 3 || (dropArealess && twiceSignedArea(cleaned) == 0.0))
    return {};
  return cleaned;
}

namespace
{

/** For each box, the others that meet it (touching counts), in index order (meetingBoxes): a slice
 *  of a thresholded noisy image holds a thousand contours and more, and every pair was compared
 *  several times per slice. */
std::vector<std::vector<std::size_t>> meetingBoxesOf(const std::vector<Box2>& boxes)
{
  std::vector<std::vector<std::size_t>> meeting(boxes.size());
  for (const auto& [i, j] : meetingBoxes(boxes))
  {
    meeting[i].push_back(j);
    meeting[j].push_back(i);
  }
  for (std::vector<std::size_t>& others : meeting)
    std::sort(others.begin(), others.end());
  return meeting;
}

} // namespace

ContourNesting orientAndNest(std::vector<Polygon2>& contours)
{
  const std::size_t n = contours.size();
  std::vector<Box2> boxes(n);
  for (std::size_t i = 0; i < n; ++i)
    boxes[i] = boundingBox(contours[i]);
  const std::vector<std::vector<std::size_t>> meeting = meetingBoxesOf(boxes);

  ContourNesting nesting;
  nesting.parent.assign(n, -1);
  nesting.depth.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    // Contours of a slice never cross, so one vertex tells whether contour i lies inside contour j.
    const Point2& probe = contours[i].front();
    for (std::size_t j : meeting[i])
    {
      const bool boxInside = boxes[j].xmin <= boxes[i].xmin && boxes[i].xmax <= boxes[j].xmax &&
                             boxes[j].ymin <= boxes[i].ymin && boxes[i].ymax <= boxes[j].ymax;
      if (!boxInside || !isInside(contours[j], probe))
        continue;
      ++nesting.depth[i];
    }
  }
  // The parent is the containing contour one level up.
  for (std::size_t i = 0; i < n; ++i)
  {
    if (nesting.depth[i] == 0)
      continue;
    const Point2& probe = contours[i].front();
    for (std::size_t j : meeting[i])
    {
      if (nesting.depth[j] == nesting.depth[i] - 1 && isInside(contours[j], probe))
      {
        nesting.parent[i] = static_cast<int>(j);
        break;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const bool counterClockwise = twiceSignedArea(contours[i]) > 0.0;
    if (counterClockwise == nesting.isHole(i))
      std::reverse(contours[i].begin(), contours[i].end());
  }
  return nesting;
}

} // namespace slicemesh

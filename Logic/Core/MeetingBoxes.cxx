#include "Core/MeetingBoxes.h"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>

namespace slicemesh
{
namespace
{

template <int D>
std::vector<std::pair<std::size_t, std::size_t>> meeting(const std::vector<std::array<double, 2 * D>>& lowHigh)
{
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, D, std::size_t>;
  std::vector<Box> tagged;
  tagged.reserve(lowHigh.size());
  for (std::size_t i = 0; i < lowHigh.size(); ++i)
  {
    std::array<double, 2 * D> bounds = lowHigh[i]; // CGAL takes non-const arrays
    bool empty = false;
    for (int a = 0; a < D; ++a)
      empty = empty || bounds[a] > bounds[D + a];
    if (!empty)
      tagged.emplace_back(bounds.data(), bounds.data() + D, i);
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  CGAL::box_self_intersection_d(tagged.begin(), tagged.end(),
                                [&](const Box& a, const Box& b)
                                { pairs.emplace_back(std::min(a.info(), b.info()), std::max(a.info(), b.info())); });
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> meetingBoxes(const std::vector<BoundingBox>& boxes)
{
  std::vector<std::array<double, 6>> lowHigh;
  lowHigh.reserve(boxes.size());
  for (const BoundingBox& b : boxes)
    lowHigh.push_back({ b.low[0], b.low[1], b.low[2], b.high[0], b.high[1], b.high[2] });
  return meeting<3>(lowHigh);
}

std::vector<std::pair<std::size_t, std::size_t>> meetingBoxes(const std::vector<Box2>& boxes)
{
  std::vector<std::array<double, 4>> lowHigh;
  lowHigh.reserve(boxes.size());
  for (const Box2& b : boxes)
    lowHigh.push_back({ b.xmin, b.ymin, b.xmax, b.ymax });
  return meeting<2>(lowHigh);
}

} // namespace slicemesh

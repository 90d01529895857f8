#include "Measures/TrianglesMeetingBoxes.h"

#include "Core/ParallelFor.h"
#include "Core/SpatialHash.h"

#include <algorithm>
#include <utility>

namespace slicemesh
{
namespace
{

/** Triangles per range of the pass over the triangles. */
constexpr std::size_t rangeSize = 1 << 14;

double widthOf(const BoundingBox& box)
{
  return std::max({ box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2] });
}

/** The cells' width: all but the widest tenth of the boxes fit in two cells a side, and a triangle
 *  of mean width (over a sample spread over the mesh) in two. */
double cellWidth(const TriangleMesh& mesh, const std::vector<BoundingBox>& boxes)
{
  std::vector<double> widths;
  widths.reserve(boxes.size());
  for (const BoundingBox& box : boxes)
    widths.push_back(widthOf(box));
  const std::size_t tenth = widths.size() - 1 - (widths.size() - 1) / 10;
  std::nth_element(widths.begin(), widths.begin() + static_cast<std::ptrdiff_t>(tenth), widths.end());
  double triangleWidth = 0.0;
  const std::size_t stride = std::max<std::size_t>(1, mesh.triangles.size() / 1024);
  std::size_t sampled = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); t += stride, ++sampled)
    triangleWidth += widthOf(boxOfTriangle(mesh, t));
  triangleWidth /= static_cast<double>(std::max<std::size_t>(1, sampled));
  return std::max({ widths[tenth], 2.0 * triangleWidth, 1e-9 });
}

} // namespace

TrianglesMeeting trianglesMeetingBoxes(const TriangleMesh& mesh, const std::vector<BoundingBox>& boxes,
                                       unsigned int threads)
{
  TrianglesMeeting meeting;
  meeting.start.assign(boxes.size() + 1, 0);
  if (boxes.empty() || mesh.triangles.empty())
    return meeting;
  SpatialHash filed(cellWidth(mesh, boxes));
  std::vector<std::uint32_t> unfiled;
  BoundingBox all; // a triangle outside it meets none: most, where the boxes are a few places
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    all.add(boxes[b]);
    if (!(filed.cellCountOf(boxes[b]) <= SpatialHash::mostCellsFiled))
      unfiled.push_back(static_cast<std::uint32_t>(b));
    else
      filed.insert(filed.cellsOf(boxes[b]), static_cast<int>(b));
  }
  using Hit = std::pair<std::uint32_t, std::uint32_t>; // (box, triangle)
  const auto hitsByRange = fixedRangeResults<std::vector<Hit>>(
    mesh.triangles.size(), rangeSize, threads,
    [&](std::vector<Hit>& hits, std::size_t first, std::size_t last)
    {
      std::vector<std::uint32_t> met;
      for (std::size_t t = first; t < last; ++t)
      {
        const BoundingBox box = boxOfTriangle(mesh, t);
        if (!all.overlaps(box))
          continue;
        met.clear();
        auto tryBox = [&](std::uint32_t b)
        {
          if (boxes[b].overlaps(box))
            met.push_back(b);
        };
        if (!(filed.cellCountOf(box) <= SpatialHash::mostCellsFiled)) // a triangle far wider than the cells
          for (std::uint32_t b = 0; b < boxes.size(); ++b)
            tryBox(b);
        else
        {
          filed.forEachIn(filed.cellsOf(box), [&](int b) { tryBox(static_cast<std::uint32_t>(b)); });
          for (std::uint32_t b : unfiled)
            tryBox(b);
        }
        std::sort(met.begin(), met.end());
        met.erase(std::unique(met.begin(), met.end()), met.end());
        for (std::uint32_t b : met)
          hits.emplace_back(b, static_cast<std::uint32_t>(t));
      }
    });
  // Counted, then placed box by box in range order: each box's triangles in increasing order.
  for (const std::vector<Hit>& hits : hitsByRange)
    for (const Hit& hit : hits)
      ++meeting.start[hit.first + 1];
  for (std::size_t b = 0; b < boxes.size(); ++b)
    meeting.start[b + 1] += meeting.start[b];
  meeting.triangles.resize(meeting.start.back());
  std::vector<std::size_t> fill(meeting.start.begin(), meeting.start.end() - 1);
  for (const std::vector<Hit>& hits : hitsByRange)
    for (const Hit& hit : hits)
      meeting.triangles[fill[hit.first]++] = hit.second;
  return meeting;
}

} // namespace slicemesh

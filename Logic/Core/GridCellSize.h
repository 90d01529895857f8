#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace slicemesh
{

/** Every how many boxes one is sampled for the median box: about 4096 in all. The median of such a
 *  sample is as good as the whole one, where a copy of every size would cost memory the size of the
 *  mesh, and, freed, would raise glibc's threshold for mapping large blocks, leaving later large
 *  blocks on the heap after they are freed (a higher peak resident memory). */
inline std::size_t cellSizeSampleStride(std::size_t boxes)
{
  return std::max<std::size_t>(1, boxes / 4096);
}

/** A uniform grid's cell size for hashing boxes (triangles' boxes): twice the median of the sampled
 *  boxes' largest sides, so that a box covers one to eight cells and a cell holds a few dozen boxes;
 *  at least `smallest` (what the grid's keys can name); doubled while the boxes would cover more
 *  than eight cells each on average (a mesh of a few long triangles), up to `extent`.
 *  `coveredAt(size)`: how many cells of that size the boxes cover in all. Returns the size and that count. */
struct CellSizeChoice
{
  double size = 0.0;
  std::uint64_t covered = 0;
};

template <typename Side, typename CoveredAt>
CellSizeChoice chooseCellSize(std::vector<Side> sampledSides, std::size_t boxes, double extent, double smallest,
                              CoveredAt&& coveredAt)
{
  CellSizeChoice choice;
  if (sampledSides.empty())
    return choice;
  const auto middle = sampledSides.begin() + static_cast<std::ptrdiff_t>(sampledSides.size() / 2);
  std::nth_element(sampledSides.begin(), middle, sampledSides.end());
  choice.size = std::max({ 2.0 * static_cast<double>(*middle), smallest, 1e-300 });
  for (;; choice.size *= 2.0)
  {
    choice.covered = coveredAt(choice.size);
    if (choice.covered <= 8 * static_cast<std::uint64_t>(boxes) || choice.size >= extent)
      return choice;
  }
}

} // namespace slicemesh

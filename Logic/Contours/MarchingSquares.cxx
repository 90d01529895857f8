#include "Contours/MarchingSquares.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

ScalarGrid2 sampleGrid(const Box2& box, double cell,
                       const std::function<void(const std::vector<Point2>&, std::vector<double>&)>& field)
{
  if (!(cell > 0.0) || !(box.xmax >= box.xmin) || !(box.ymax >= box.ymin))
    throw Error("marching squares: the grid needs a positive cell size and a non-empty box");
  ScalarGrid2 grid;
  grid.cell = cell;
  grid.x0 = box.xmin;
  grid.y0 = box.ymin;
  grid.nx = static_cast<std::size_t>(std::ceil((box.xmax - box.xmin) / cell)) + 1;
  grid.ny = static_cast<std::size_t>(std::ceil((box.ymax - box.ymin) / cell)) + 1;
  grid.nx = std::max<std::size_t>(grid.nx, 2);
  grid.ny = std::max<std::size_t>(grid.ny, 2);
  std::vector<Point2> nodes;
  nodes.reserve(grid.nx * grid.ny);
  for (std::size_t j = 0; j < grid.ny; ++j)
    for (std::size_t i = 0; i < grid.nx; ++i)
      nodes.push_back(grid.node(i, j));
  field(nodes, grid.values);
  if (grid.values.size() != nodes.size())
    throw Error("marching squares: the field gave the wrong number of values");
  return grid;
}

std::vector<Polygon2> zeroContours(const ScalarGrid2& grid, double minArea)
{
  const std::size_t nx = grid.nx, ny = grid.ny;
  std::vector<Polygon2> loops;
  if (nx < 2 || ny < 2)
    return loops;

  // A node is inside when its value is negative and it is not on the border; zero counts as outside.
  auto interior = [&](std::size_t i, std::size_t j) { return i > 0 && j > 0 && i + 1 < nx && j + 1 < ny; };
  auto inside = [&](std::size_t i, std::size_t j) { return interior(i, j) && grid.at(i, j) < 0.0; };
  // The value used for interpolation: a border node is pushed just outside.
  auto value = [&](std::size_t i, std::size_t j) {
    const double v = grid.at(i, j);
    return interior(i, j) ? v : std::max(v, 0.0);
  };

  // Crossings are named by their grid edge: horizontal edges first, then vertical ones.
  const std::size_t horizontalEdges = (nx - 1) * ny;
  auto horizontal = [&](std::size_t i, std::size_t j) { return j * (nx - 1) + i; };
  auto vertical = [&](std::size_t i, std::size_t j) { return horizontalEdges + j * nx + i; };
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> next(horizontalEdges + nx * (ny - 1), none);

  auto crossingPoint = [&](std::size_t edge) {
    std::size_t i0, j0, i1, j1;
    if (edge < horizontalEdges)
    {
      i0 = edge % (nx - 1);
      j0 = edge / (nx - 1);
      i1 = i0 + 1;
      j1 = j0;
    }
    else
    {
      i0 = (edge - horizontalEdges) % nx;
      j0 = (edge - horizontalEdges) / nx;
      i1 = i0;
      j1 = j0 + 1;
    }
    const double v0 = value(i0, j0), v1 = value(i1, j1);
    // Linear interpolation of the zero; kept off the nodes so crossings of different edges differ.
    const double t = std::clamp(v0 == v1 ? 0.5 : v0 / (v0 - v1), 1e-3, 1.0 - 1e-3);
    const Point2 a = grid.node(i0, j0), b = grid.node(i1, j1);
    return Point2{ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
  };

  for (std::size_t j = 0; j + 1 < ny; ++j)
  {
    for (std::size_t i = 0; i + 1 < nx; ++i)
    {
      // Corners counter-clockwise, and the edge leaving each corner.
      const std::size_t ci[4] = { i, i + 1, i + 1, i };
      const std::size_t cj[4] = { j, j, j + 1, j + 1 };
      const std::size_t edges[4] = { horizontal(i, j), vertical(i + 1, j), horizontal(i, j + 1), vertical(i, j) };
      bool in[4];
      for (int k = 0; k < 4; ++k)
        in[k] = inside(ci[k], cj[k]);
      // Crossings in counter-clockwise order; an exit goes from inside to outside along the boundary.
      std::size_t crossing[4];
      bool exits[4];
      int count = 0;
      for (int k = 0; k < 4; ++k)
        if (in[k] != in[(k + 1) % 4])
        {
          crossing[count] = edges[k];
          exits[count] = in[k];
          ++count;
        }
      if (count == 0)
        continue;
      // Rotate so the list starts with an exit: exit, entry[, exit, entry].
      int first = exits[0] ? 0 : 1;
      auto at = [&](int k) { return crossing[(first + k) % count]; };
      // Each segment runs from an exit to an entry, which keeps the solid on its left.
      if (count == 2)
        next[at(0)] = at(1);
      else
      {
        double mean = 0.0;
        for (int k = 0; k < 4; ++k)
          mean += value(ci[k], cj[k]);
        if (mean < 0.0) // the inside corners are joined: cut off the outside corners
        {
          next[at(0)] = at(1);
          next[at(2)] = at(3);
        }
        else // the inside corners are separate: cut off each of them
        {
          next[at(0)] = at(3);
          next[at(2)] = at(1);
        }
      }
    }
  }

  // Chain the segments into loops; every crossing has one successor and one predecessor.
  std::vector<bool> used(next.size(), false);
  for (std::size_t start = 0; start < next.size(); ++start)
  {
    if (next[start] == none || used[start])
      continue;
    Polygon2 loop;
    std::size_t e = start;
    while (e != none && !used[e])
    {
      used[e] = true;
      loop.push_back(crossingPoint(e));
      e = next[e];
    }
    if (e != start)
      throw Error("marching squares: an open chain (internal error)");
    if (loop.size() >= 3 && std::abs(0.5 * twiceSignedArea(loop)) >= minArea)
      loops.push_back(std::move(loop));
  }
  return loops;
}

} // namespace slicemesh

// Closed contours of the zero level set of a scalar field sampled on a planar grid.
#ifndef MarchingSquares_h
#define MarchingSquares_h

#include "Core/PlanarGeometry.h"

#include <functional>
#include <vector>

namespace slicemesh
{

/** Values at the nodes (x0 + i * cell, y0 + j * cell), i < nx, j < ny, stored row by row. */
struct ScalarGrid2
{
  double x0 = 0.0;
  double y0 = 0.0;
  double cell = 1.0;
  std::size_t nx = 0;
  std::size_t ny = 0;
  std::vector<double> values;

  double at(std::size_t i, std::size_t j) const { return values[j * nx + i]; }
  Point2 node(std::size_t i, std::size_t j) const
  {
    return { x0 + static_cast<double>(i) * cell, y0 + static_cast<double>(j) * cell };
  }
};

/** A grid over box (grown to whole cells) with values from field(all nodes), which fills one value per
 *  node in the order given. */
ScalarGrid2 sampleGrid(const Box2& box, double cell,
                       const std::function<void(const std::vector<Point2>&, std::vector<double>&)>& field);

/** The zero level set of the grid as closed polygons (marching squares). The solid is where the
 *  value is negative; outer boundaries come counter-clockwise and holes clockwise. Nodes on the
 *  grid's border count as outside, so every contour closes inside the grid. Crossings are placed on
 *  cell edges by linear interpolation; an ambiguous (saddle) cell joins its negative corners when
 *  the mean of its four values is negative and separates them otherwise, a per-cell rule that
 *  neighbouring cells never contradict. Loops of area below minArea (mm^2) are dropped. */
std::vector<Polygon2> zeroContours(const ScalarGrid2& grid, double minArea = 0.0);

} // namespace slicemesh

#endif

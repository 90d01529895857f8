#include "Finishing/SurfaceSmoothing.h"

#include "Core/AreaNormal.h"
#include "Core/ParallelFor.h"
#include "Finishing/EllipsoidClamp.h"
#include "Finishing/PackedTaubinSteps.h"
#include "Measures/MeshComponents.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace slicemesh
{
namespace
{

/** The neighbours of every vertex (vertices sharing an edge with it), in compressed rows. */
struct VertexNeighbours
{
  std::vector<std::size_t> first; ///< neighbours of v are ids[first[v]] .. ids[first[v + 1]] - 1
  std::vector<std::int32_t> ids;
  /** 1 / the number of neighbours of v (0 without any): the mean is taken hundreds of times per
   *  vertex, and a division waited on is most of a step's time. */
  std::vector<double> inverseCount;
};

/** VertexNeighbours::inverseCount of a vertex with `count` neighbours. */
double inverseCountOf(std::size_t count)
{
  return count > 0 ? 1.0 / static_cast<double>(count) : 0.0;
}

/** The neighbours of every vertex, numbered by `rank` (the vertex's place in the smoothing's order),
 *  in increasing order. Each corner of a triangle has the two others for neighbours: they are
 *  counted and placed per vertex, then each vertex's few are sorted and made unique, the vertices
 *  side by side on `threads` threads. (One sort of every edge of the mesh ran on one thread while
 *  the other waited.) */
VertexNeighbours neighboursOf(const TriangleMesh& mesh, const std::vector<std::int32_t>& rank, unsigned int threads)
{
  const std::size_t vertices = mesh.points.size();
  std::vector<std::size_t> start(vertices + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t corner : t)
      start[static_cast<std::size_t>(rank[static_cast<std::size_t>(corner)]) + 1] += 2;
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::int32_t> around(start[vertices]);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const Triangle& t : mesh.triangles)
      for (int corner = 0; corner < 3; ++corner)
      {
        std::size_t& at = next[static_cast<std::size_t>(rank[static_cast<std::size_t>(t[corner])])];
        around[at++] = rank[static_cast<std::size_t>(t[(corner + 1) % 3])];
        around[at++] = rank[static_cast<std::size_t>(t[(corner + 2) % 3])];
      }
  }
  std::vector<std::size_t> distinct(vertices, 0);
  parallelForRanges(vertices, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        const auto from = around.begin() + static_cast<std::ptrdiff_t>(start[v]);
                        const auto to = around.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
                        std::sort(from, to);
                        distinct[v] = static_cast<std::size_t>(std::unique(from, to) - from);
                      }
                    });
  VertexNeighbours neighbours;
  neighbours.first.assign(vertices + 1, 0);
  neighbours.inverseCount.resize(vertices);
  for (std::size_t v = 0; v < vertices; ++v)
  {
    neighbours.first[v + 1] = neighbours.first[v] + distinct[v];
    neighbours.inverseCount[v] = inverseCountOf(distinct[v]);
  }
  neighbours.ids.resize(neighbours.first[vertices]);
  parallelForRanges(vertices, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                        std::copy_n(around.begin() + static_cast<std::ptrdiff_t>(start[v]), distinct[v],
                                    neighbours.ids.begin() + static_cast<std::ptrdiff_t>(neighbours.first[v]));
                    });
  return neighbours;
}

/** The vertices in the order the smoothing visits them: breadth first over the edges, each connected
 *  piece from its lowest vertex, a vertex's neighbours in increasing order. Two neighbours are then
 *  at most one level of the search apart, so within two levels' rows of each other (under 700 on
 *  the thick scaling ellipsoid's 130,000 vertices), and a step reads its neighbours from the cache.
 *  (In Morton order of a grid over the bounding box, 1% of the edges joined vertices tens of
 *  thousands of rows apart, and a step waited on memory for them; in the remesh's own order,
 *  splits appended at the end, far more.) */
std::vector<std::int32_t> breadthFirstOrder(const VertexNeighbours& neighbours)
{
  const std::size_t vertices = neighbours.first.size() - 1;
  std::vector<char> reached(vertices, 0);
  std::vector<std::int32_t> order;
  order.reserve(vertices);
  for (std::size_t seed = 0; seed < vertices; ++seed)
  {
    if (reached[seed])
      continue;
    reached[seed] = 1;
    order.push_back(static_cast<std::int32_t>(seed));
    for (std::size_t head = order.size() - 1; head < order.size(); ++head)
    {
      const auto v = static_cast<std::size_t>(order[head]);
      for (std::size_t k = neighbours.first[v]; k < neighbours.first[v + 1]; ++k)
      {
        const auto u = static_cast<std::size_t>(neighbours.ids[k]);
        if (!reached[u])
        {
          reached[u] = 1;
          order.push_back(static_cast<std::int32_t>(u));
        }
      }
    }
  }
  return order;
}

/** The neighbours read back from the slots made of them (NeighbourSlots), as they were. */
VertexNeighbours fromSlots(const NeighbourSlots& slots, unsigned int threads)
{
  VertexNeighbours neighbours;
  slots.rowsInto(neighbours.first, neighbours.ids, threads);
  neighbours.inverseCount.resize(neighbours.first.size() - 1);
  for (std::size_t v = 0; v + 1 < neighbours.first.size(); ++v)
    neighbours.inverseCount[v] = inverseCountOf(neighbours.first[v + 1] - neighbours.first[v]);
  return neighbours;
}

/** The neighbours by vertex (`byVertex`) with the rows in `order` and numbered by rank (row i holds
 *  vertex order[i]'s, as the ranks of their vertices): what neighboursOf(mesh, rank) gives, from the
 *  table already made rather than from the triangles again, whose two passes ran on one thread. */
VertexNeighbours renumbered(const VertexNeighbours& byVertex, const std::vector<std::int32_t>& order,
                            const std::vector<std::int32_t>& rank, unsigned int threads)
{
  const std::size_t vertices = order.size();
  VertexNeighbours rows;
  rows.first.assign(vertices + 1, 0);
  rows.inverseCount.resize(vertices);
  for (std::size_t row = 0; row < vertices; ++row)
  {
    const auto v = static_cast<std::size_t>(order[row]);
    rows.first[row + 1] = rows.first[row] + (byVertex.first[v + 1] - byVertex.first[v]);
    rows.inverseCount[row] = byVertex.inverseCount[v];
  }
  rows.ids.resize(rows.first[vertices]);
  parallelForRanges(vertices, threads,
                    [&](std::size_t firstRow, std::size_t lastRow)
                    {
                      for (std::size_t row = firstRow; row < lastRow; ++row)
                      {
                        const auto v = static_cast<std::size_t>(order[row]);
                        const auto to = rows.ids.begin() + static_cast<std::ptrdiff_t>(rows.first[row]);
                        for (std::size_t k = byVertex.first[v]; k < byVertex.first[v + 1]; ++k)
                          to[static_cast<std::ptrdiff_t>(k - byVertex.first[v])] =
                            rank[static_cast<std::size_t>(byVertex.ids[k])];
                        std::sort(to, rows.ids.begin() + static_cast<std::ptrdiff_t>(rows.first[row + 1]));
                      }
                    });
  return rows;
}

/** Where a vertex may go: within the ellipsoid of semi-axes `bound` around its start (inactive:
 *  anywhere); once `holdFeatures` is called, the vertices not flagged `held` (away from sharp
 *  features) within the ellipsoid of semi-axes `wide`. */
class DisplacementBound
{
public:
  DisplacementBound(const std::vector<Point3>& start, const std::array<double, 3>& bound, bool active)
    : start(start), active(active), inverse(inverseOf(bound)), wideInverse(inverse)
  {
  }

  void holdFeatures(const std::vector<char>& held, const std::array<double, 3>& wide)
  {
    this->held = &held;
    wideInverse = inverseOf(wide);
  }

  /** p, or if it has left the ellipsoid, the ellipsoid's point nearest to it. */
  Point3 clamped(const Point3& p, std::size_t v) const
  {
    if (!active)
      return p;
    const Point3& s = start[v];
    const double dx = p.x - s.x, dy = p.y - s.y, dz = p.z - s.z;
    const std::array<double, 3>& axes = held && !(*held)[v] ? wideInverse : inverse;
    // The displacement in units of the bound: 1 on the ellipsoid.
    const double ux = dx * axes[0], uy = dy * axes[1], uz = dz * axes[2];
    const double reachSquared = ux * ux + uy * uy + uz * uz;
    if (reachSquared <= 1.0)
      return p;
    const std::array<double, 3> f =
      nearestOnEllipsoidFactors<double>({ ux, uy, uz }, { axes[0] * axes[0], axes[1] * axes[1], axes[2] * axes[2] });
    return { s.x + f[0] * dx, s.y + f[1] * dy, s.z + f[2] * dz };
  }

private:
  /** The reciprocal semi-axes: the clamp runs once per vertex and step, and multiplies. */
  static std::array<double, 3> inverseOf(const std::array<double, 3>& axes)
  {
    return { 1.0 / axes[0], 1.0 / axes[1], 1.0 / axes[2] };
  }

  const std::vector<Point3>& start;
  bool active;
  std::array<double, 3> inverse;
  std::array<double, 3> wideInverse;
  const std::vector<char>* held = nullptr;
};

/** The mean of row v's neighbours, or the point itself if it has none. Inlined into each step's loop:
 *  called, its 24-byte result came back through memory before the next row's neighbours could be
 *  loaded (the smoothing alone 10% faster inlined). */
inline __attribute__((always_inline)) Point3 neighbourMean(const std::vector<Point3>& points, const VertexNeighbours& neighbours, std::size_t v)
{
  const std::size_t begin = neighbours.first[v], end = neighbours.first[v + 1];
  if (begin == end)
    return points[v];
  double x = 0.0, y = 0.0, z = 0.0;
  for (std::size_t i = begin; i < end; ++i)
  {
    const Point3& q = points[static_cast<std::size_t>(neighbours.ids[i])];
    x += q.x;
    y += q.y;
    z += q.z;
  }
  const double inverse = neighbours.inverseCount[v];
  return { x * inverse, y * inverse, z * inverse };
}

/** Signed volume and area of every component (by the component of each triangle's first vertex).
 *  With `held` (a flag per vertex, not empty), each triangle's area counts by the share of its
 *  corners not held: the volume an offset of the others gains per unit. Fixed ranges of triangles
 *  side by side, each range's sums added in range order: the same sums on any number of threads.
 *  (On one thread, with the offset's normals, it kept the other cores waiting after the smoothing.) */
void measureComponents(const TriangleMesh& mesh, const std::vector<std::size_t>& component, std::vector<double>& volume,
                       std::vector<double>& area, unsigned int threads, const std::vector<char>& held = {})
{
  constexpr std::size_t trianglesPerRange = 16384;
  const std::size_t components = volume.size();
  struct RangeSums
  {
    std::vector<double> volume, area; // by component
  };
  const std::vector<RangeSums> ranges = fixedRangeResults<RangeSums>(
    mesh.triangles.size(), trianglesPerRange, threads,
    [&](RangeSums& sums, std::size_t first, std::size_t last)
    {
      sums.volume.assign(components, 0.0);
      sums.area.assign(components, 0.0);
      for (std::size_t f = first; f < last; ++f)
      {
        const Triangle& t = mesh.triangles[f];
        const Point3 n = areaNormal(mesh, t);
        const Point3& a = mesh.points[t[0]];
        const std::size_t k = component[static_cast<std::size_t>(t[0])];
        sums.volume[k] += (a.x * n.x + a.y * n.y + a.z * n.z) / 6.0;
        double share = 1.0;
        if (!held.empty())
          share = static_cast<double>(3 - (held[static_cast<std::size_t>(t[0])] != 0) -
                                      (held[static_cast<std::size_t>(t[1])] != 0) -
                                      (held[static_cast<std::size_t>(t[2])] != 0)) /
                  3.0;
        sums.area[k] += share * 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      }
    });
  std::fill(volume.begin(), volume.end(), 0.0);
  std::fill(area.begin(), area.end(), 0.0);
  for (const RangeSums& sums : ranges)
    for (std::size_t k = 0; k < components; ++k)
    {
      volume[k] += sums.volume[k];
      area[k] += sums.area[k];
    }
}

/** n scaled to unit length; a zero vector stays zero. */
Point3 unitOrZero(const Point3& n)
{
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return length > 0.0 ? Point3{ n.x / length, n.y / length, n.z / length } : n;
}

/** Unit vertex normals: the sum of the area-weighted normals of the vertex's triangles (added in
 *  triangle order; the triangles' normals found side by side). */
std::vector<Point3> vertexNormals(const TriangleMesh& mesh, unsigned int threads)
{
  std::vector<Point3> faceNormals(mesh.triangles.size());
  parallelForRanges(mesh.triangles.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t f = first; f < last; ++f)
                        faceNormals[f] = areaNormal(mesh, mesh.triangles[f]);
                    });
  std::vector<Point3> normals(mesh.points.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Point3& n = faceNormals[f];
    for (std::int32_t v : mesh.triangles[f])
    {
      normals[v].x += n.x;
      normals[v].y += n.y;
      normals[v].z += n.z;
    }
  }
  parallelForRanges(normals.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                        normals[v] = unitOrZero(normals[v]);
                    });
  return normals;
}

/** Where one relaxation step takes row v: half way towards the mean of its neighbours, within its
 *  tangent plane (unit normal n: the displacement's part along it removed), clamped to its bound. */
Point3 relaxedPoint(const std::vector<Point3>& points, const VertexNeighbours& neighbours, std::size_t v, const Point3& n,
                    const DisplacementBound& bound)
{
  const Point3 mean = neighbourMean(points, neighbours, v);
  double dx = mean.x - points[v].x, dy = mean.y - points[v].y, dz = mean.z - points[v].z;
  const double along = dx * n.x + dy * n.y + dz * n.z;
  dx -= along * n.x;
  dy -= along * n.y;
  dz -= along * n.z;
  return bound.clamped({ points[v].x + 0.5 * dx, points[v].y + 0.5 * dy, points[v].z + 0.5 * dz }, v);
}

/** The triangles around every row of the smoothing's order, in compressed rows: those of row i are
 *  ids[first[i]] .. ids[first[i + 1]] - 1, in increasing order. */
struct RowTriangles
{
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> ids; ///< triangle indices (a mesh's indices are 32-bit)
};

RowTriangles trianglesOfRows(const TriangleMesh& mesh, const std::vector<std::int32_t>& rank)
{
  RowTriangles rows;
  rows.first.assign(rank.size() + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t)
      ++rows.first[static_cast<std::size_t>(rank[static_cast<std::size_t>(v)]) + 1];
  std::partial_sum(rows.first.begin(), rows.first.end(), rows.first.begin());
  rows.ids.resize(rows.first.back());
  std::vector<std::size_t> next(rows.first.begin(), rows.first.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::int32_t v : mesh.triangles[f])
      rows.ids[next[static_cast<std::size_t>(rank[static_cast<std::size_t>(v)])]++] = static_cast<std::uint32_t>(f);
  return rows;
}

/** The unit normal of row v: the sum of its triangles' area normals (`around`, in increasing order),
 *  the corners taken from `points` through `rank`. */
Point3 rowNormal(const std::vector<Point3>& points, const TriangleMesh& mesh, const std::vector<std::int32_t>& rank,
                 const RowTriangles& around, std::size_t v)
{
  auto at = [&](std::int32_t u) -> const Point3& { return points[static_cast<std::size_t>(rank[static_cast<std::size_t>(u)])]; };
  Point3 normal{ 0.0, 0.0, 0.0 };
  for (std::size_t k = around.first[v]; k < around.first[v + 1]; ++k)
  {
    const Triangle& t = mesh.triangles[around.ids[k]];
    const Point3 n = areaNormal(at(t[0]), at(t[1]), at(t[2]));
    normal = { normal.x + n.x, normal.y + n.y, normal.z + n.z };
  }
  return unitOrZero(normal);
}

/** The rows on a sharp feature: one of the row's triangles turns from the row's normal by more than
 *  `angleDegrees`; and the rows within `rings` rings of one, whose filter steps would round the
 *  feature too. */
std::vector<char> sharpFeatureRows(const std::vector<Point3>& points, const TriangleMesh& mesh,
                                   const std::vector<std::int32_t>& rank, const RowTriangles& around,
                                   double angleDegrees, int rings, unsigned int threads)
{
  auto at = [&](std::int32_t u) -> const Point3& { return points[static_cast<std::size_t>(rank[static_cast<std::size_t>(u)])]; };
  const double cosine = std::cos(angleDegrees * M_PI / 180.0);
  std::vector<char> sharp(points.size(), 0);
  parallelForRanges(points.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        const Point3 n = rowNormal(points, mesh, rank, around, v);
                        for (std::size_t k = around.first[v]; k < around.first[v + 1] && !sharp[v]; ++k)
                        {
                          const Triangle& t = mesh.triangles[around.ids[k]];
                          const Point3 m = unitOrZero(areaNormal(at(t[0]), at(t[1]), at(t[2])));
                          sharp[v] = m.x * n.x + m.y * n.y + m.z * n.z < cosine;
                        }
                      }
                    });
  // The rings are grown over the mesh's own vertex numbers, then put back in the smoothing's order.
  std::vector<char> byVertex(sharp.size());
  for (std::size_t v = 0; v < byVertex.size(); ++v)
    byVertex[v] = sharp[static_cast<std::size_t>(rank[v])];
  growByRings(mesh, byVertex, rings);
  for (std::size_t v = 0; v < byVertex.size(); ++v)
    sharp[static_cast<std::size_t>(rank[v])] = byVertex[v];
  return sharp;
}

/** One step of tangential relaxation: every vertex moves half way towards the mean of its neighbours,
 *  within its tangent plane (the displacement's part along the vertex normal removed), clamped to
 *  its bound. `points` and the neighbours are in the smoothing's order (`rank[v]` is vertex v's
 *  row), `mesh` gives the triangles; each row's normal is the sum of its triangles' area normals,
 *  taken row by row so that the rows run side by side. */
void tangentialStep(std::vector<Point3>& points, const TriangleMesh& mesh, const std::vector<std::int32_t>& rank,
                    const RowTriangles& around, const VertexNeighbours& neighbours, std::vector<Point3>& scratch,
                    const DisplacementBound& bound, unsigned int threads)
{
  parallelForRanges(points.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                        scratch[v] = relaxedPoint(points, neighbours, v, rowNormal(points, mesh, rank, around, v), bound);
                    });
  points.swap(scratch);
}

/** `steps` more relaxation steps (as tangentialStep) for the vertices of the triangles that have an
 *  angle under 30 degrees, and for their neighbours, within the bound. Rows as in tangentialStep;
 *  `mesh` gives the triangles only. Worked on that patch alone, so that the cost follows the narrow
 *  triangles (a few on most surfaces), not the mesh; its rows side by side on `threads` threads,
 *  each row's normal summed over its own triangles in one order, so the result does not depend on
 *  the number. Whether there was any vertex to relax. */
bool relaxAroundNarrowTriangles(std::vector<Point3>& points, const TriangleMesh& mesh,
                                const std::vector<std::int32_t>& rank, const VertexNeighbours& neighbours,
                                const RowTriangles& around, const DisplacementBound& bound, int steps,
                                unsigned int threads, const std::vector<char>& fixed = {})
{
  if (steps <= 0)
    return false;
  auto row = [&rank](std::int32_t v) { return static_cast<std::size_t>(rank[static_cast<std::size_t>(v)]); };
  const double cos30 = std::sqrt(3.0) / 2.0;
  std::vector<char> narrowTriangle(mesh.triangles.size(), 0);
  parallelForRanges(mesh.triangles.size(), threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t f = first; f < last; ++f)
                      {
                        const Triangle& t = mesh.triangles[f];
                        narrowTriangle[f] =
                          smallestAngleCosine(points[row(t[0])], points[row(t[1])], points[row(t[2])]) > cos30;
                      }
                    });
  std::vector<char> narrow(points.size(), 0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (narrowTriangle[f])
      for (std::int32_t v : mesh.triangles[f])
        narrow[row(v)] = 1;
  std::vector<std::size_t> rows; // the narrow triangles' vertices and their neighbours
  std::vector<char> moving = narrow;
  for (std::size_t r = 0; r < narrow.size(); ++r)
    if (narrow[r])
      for (std::size_t k = neighbours.first[r]; k < neighbours.first[r + 1]; ++k)
        moving[static_cast<std::size_t>(neighbours.ids[k])] = 1;
  for (std::size_t r = 0; r < moving.size(); ++r)
    if (moving[r] && (fixed.empty() || !fixed[r]))
      rows.push_back(r);
  if (rows.empty())
    return false;
  std::vector<Point3> targets(rows.size());
  for (int step = 0; step < steps; ++step)
  {
    parallelForRanges(rows.size(), threads,
                      [&](std::size_t first, std::size_t last)
                      {
                        for (std::size_t i = first; i < last; ++i)
                          targets[i] =
                            relaxedPoint(points, neighbours, rows[i], rowNormal(points, mesh, rank, around, rows[i]), bound);
                      },
                      1024);
    for (std::size_t i = 0; i < rows.size(); ++i)
      points[rows[i]] = targets[i];
  }
  return true;
}

/** Gives every component back the signed volume it had (`target`) by moving its vertices along their
 *  normals by one common distance (a few Newton steps: the volume grows by the area per unit of
 *  offset). Taubin's filter keeps large shapes, but shrinks a structure a few edges across, whose
 *  whole shape lies above the pass band: a vessel two voxels wide would lose half its volume. */
void restoreVolumes(TriangleMesh& mesh, const std::vector<std::size_t>& component, const std::vector<double>& target,
                    unsigned int threads, const std::vector<char>& held = {}, double maxOffset = 0.0)
{
  std::vector<double> volume(target.size()), area(target.size()), offset(target.size()), total(target.size(), 0.0);
  for (int step = 0; step < 4; ++step)
  {
    measureComponents(mesh, component, volume, area, threads, held);
    bool done = true;
    for (std::size_t k = 0; k < target.size(); ++k)
    {
      offset[k] = area[k] > 0.0 ? (target[k] - volume[k]) / area[k] : 0.0;
      if (maxOffset > 0.0)
      {
        offset[k] = std::clamp(offset[k], -maxOffset - total[k], maxOffset - total[k]);
        total[k] += offset[k];
      }
      done = done && std::abs(target[k] - volume[k]) <= 1e-9 * std::abs(target[k]);
    }
    if (done)
      return;
    const std::vector<Point3> normals = vertexNormals(mesh, threads);
    parallelForRanges(mesh.points.size(), threads,
                      [&](std::size_t first, std::size_t last)
                      {
                        for (std::size_t v = first; v < last; ++v)
                        {
                          if (!held.empty() && held[v])
                            continue;
                          const double d = offset[component[v]];
                          mesh.points[v].x += d * normals[v].x;
                          mesh.points[v].y += d * normals[v].y;
                          mesh.points[v].z += d * normals[v].z;
                        }
                      });
  }
}

} // namespace

int pairsBeforeFeaturesHeld(const SurfaceSmoothingOptions& options)
{
  return std::clamp(options.featurePairs, 0, std::max(0, options.iterations));
}

std::array<double, 3> boundAwayFromFeatures(const SurfaceSmoothingOptions& options)
{
  std::array<double, 3> bound{};
  for (int axis = 0; axis < 3; ++axis)
    bound[axis] = std::max(options.maxDisplacement[axis], options.maxDisplacementAwayFromFeatures[axis]);
  return bound;
}

bool relaxNarrowTriangles(TriangleMesh& mesh, const std::vector<Point3>& start, const std::vector<char>& fixed,
                          const SurfaceSmoothingOptions& options, unsigned int threads)
{
  if (mesh.triangles.empty() || start.size() != mesh.points.size() || fixed.size() != mesh.points.size())
    return false;
  const bool bounded = std::any_of(options.maxDisplacement.begin(), options.maxDisplacement.end(),
                                   [](double axis) { return axis > 0.0; });
  // The plain bound: this relaxation follows putting vertices back where the smoothing made sheets
  // cross, and widened there it left natbrainlab with 1.18% of its triangles under 30 degrees, not 0.96%.
  const DisplacementBound bound(start, options.maxDisplacement, bounded);
  std::vector<std::int32_t> rank(mesh.points.size()); // the mesh's own order: vertex v is row v
  std::iota(rank.begin(), rank.end(), 0);
  return relaxAroundNarrowTriangles(mesh.points, mesh, rank, neighboursOf(mesh, rank, threads), trianglesOfRows(mesh, rank),
                                    bound, options.narrowTriangleRelaxations, threads, fixed);
}

void offsetToVolume(TriangleMesh& mesh, double volume, const std::vector<char>& held, double maxOffset,
                    unsigned int threads)
{
  if (mesh.triangles.empty())
    return;
  restoreVolumes(mesh, std::vector<std::size_t>(mesh.points.size(), 0), { volume }, threads, held, maxOffset);
}

void smoothSurface(TriangleMesh& mesh, const SurfaceSmoothingOptions& options, unsigned int threads,
                   const std::vector<char>& held, std::vector<Point3>* unsmoothed)
{
  if (options.iterations <= 0 || mesh.triangles.empty())
  {
    if (unsmoothed)
      *unsmoothed = mesh.points;
    return;
  }
  if (!(options.passBand > 0.0 && options.passBand < 1.0))
    throw Error("surface smoothing: the pass band must lie between 0 and 1");
  // 0.63 rather than Taubin's 0.5: the same pass band is reached in two thirds of the pairs
  // (measured: 100 pairs at 0.63 leave the benchmark's surfaces where 150 at 0.5 did), and every
  // mode of the umbrella operator (0 < k < 2) still shrinks, |(1 - lambda k)(1 - mu k)| < 1.
  const double lambda = 0.63;
  const double mu = 1.0 / (options.passBand - 1.0 / lambda);
  std::size_t components = 0;
  const std::vector<std::size_t> component = vertexComponents(mesh, components);
  std::vector<double> volume(components), area(components);
  measureComponents(mesh, component, volume, area, threads);

  const bool bounded = std::any_of(options.maxDisplacement.begin(), options.maxDisplacement.end(),
                                   [](double axis) { return axis > 0.0; });
  if (bounded && !std::all_of(options.maxDisplacement.begin(), options.maxDisplacement.end(),
                              [](double axis) { return axis > 0.0 && std::isfinite(axis); }))
    throw Error("surface smoothing: the displacement bound must be positive along every axis, or 0 along all");
  // The steps run on the vertices in breadth-first order (points[i] is vertex order[i]).
  std::vector<std::int32_t> rank(mesh.points.size());
  std::iota(rank.begin(), rank.end(), 0);
  VertexNeighbours neighbours = neighboursOf(mesh, rank, threads); // by vertex, then by rank below
  const std::vector<std::int32_t> order = breadthFirstOrder(neighbours);
  for (std::size_t i = 0; i < order.size(); ++i)
    rank[static_cast<std::size_t>(order[i])] = static_cast<std::int32_t>(i);
  neighbours = renumbered(neighbours, order, rank, threads);
  std::vector<Point3> start(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    start[i] = mesh.points[static_cast<std::size_t>(order[i])];
  // The mesh's points are `start` by row now, and are written back from `points` at the end: held
  // beside both, they were part of a large piece's peak memory.
  mesh.points = std::vector<Point3>();
  std::vector<Point3> points(order.size());
  DisplacementBound bound(start, options.maxDisplacement, bounded);
  // Vertices held where they are (drawn contours' own), by row: they take each pair's steps, as a
  // sharp feature's do (below), and are put back after the pair and after each relaxation.
  std::vector<char> heldRow(held.empty() ? 0 : order.size(), 0);
  std::vector<std::size_t> heldRows;
  for (std::size_t r = 0; r < heldRow.size(); ++r)
    if (held[static_cast<std::size_t>(order[r])])
    {
      heldRow[r] = 1;
      heldRows.push_back(r);
    }
  auto putBackHeld = [&]()
  {
    for (std::size_t r : heldRows)
      points[r] = start[r];
  };
  const int wholePairs = pairsBeforeFeaturesHeld(options);
  const RowTriangles around = trianglesOfRows(mesh, rank);
  std::vector<char> sharp;
  {
    // The neighbours' rows are dropped while the pairs run on their slots, and read back from them
    // after: held side by side, both were part of a large piece's peak memory.
    const NeighbourSlots slots(neighbours.first, neighbours.ids, threads);
    neighbours = {};
    {
      // On a packed copy of the points (PackedTaubinSteps.h), freed before the relaxation's.
      TaubinPairs pairs(start, slots, options.maxDisplacement, bounded, heldRows);
      pairs.run(wholePairs, lambda, mu, threads);
      if (options.iterations > wholePairs)
      {
        // Found after the first pairs, which take the staircase's own creases out. A held vertex still
        // takes each pair's steps, so that its neighbours see the filter's shrinking and inflating steps
        // alike, and is put back after it: held through both, a feature pulled its neighbours outwards
        // in every inflating step (a torus's mean distance 7% up, where this gives 2.5% down).
        pairs.unpackInto(points);
        sharp = sharpFeatureRows(points, mesh, rank, around, options.featureAngle, 2, threads);
        bound.holdFeatures(sharp, boundAwayFromFeatures(options)); // the relaxation below keeps the plain bound on them
        pairs.holdFeatures(sharp, boundAwayFromFeatures(options));
        pairs.run(options.iterations - wholePairs, lambda, mu, threads);
      }
      pairs.unpackInto(points);
      putBackHeld(); // exactly, not as rounded in the packed copy
    }
    neighbours = fromSlots(slots, threads);
  }
  std::vector<Point3> scratch(order.size());
  // The filter moves vertices along the surface too, and where it folds sharply (a tract a voxel or
  // two thick) it crowds them: triangles it leaves with small angles, relaxed back along the surface.
  for (int i = 0; i < options.tangentialRelaxations; ++i)
  {
    tangentialStep(points, mesh, rank, around, neighbours, scratch, bound, threads);
    putBackHeld();
  }
  relaxAroundNarrowTriangles(points, mesh, rank, neighbours, around, bound, options.narrowTriangleRelaxations, threads,
                             heldRow);
  mesh.points.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    mesh.points[static_cast<std::size_t>(order[i])] = points[i];
  // A component a few edges across has no shape below the pass band: the filter collapses it, and
  // no offset can give a speck its volume back. Such a component keeps its unsmoothed vertices.
  std::vector<double> smoothedVolume(components), smoothedArea(components);
  measureComponents(mesh, component, smoothedVolume, smoothedArea, threads);
  std::vector<bool> collapsed(components);
  for (std::size_t k = 0; k < components; ++k)
    collapsed[k] = !(smoothedArea[k] > 0.0 && smoothedVolume[k] * volume[k] > 0.0 &&
                     std::abs(smoothedVolume[k]) >= 0.5 * std::abs(volume[k]));
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (collapsed[component[v]])
      mesh.points[v] = start[static_cast<std::size_t>(rank[v])];
  if (unsmoothed)
  {
    unsmoothed->resize(mesh.points.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      (*unsmoothed)[v] = start[static_cast<std::size_t>(rank[v])];
  }
  // Held vertices leave the others to make up the volume, and where they are few (the cap of a wall
  // thinner than an edge) no further than the filter's own bound.
  restoreVolumes(mesh, component, volume, threads, held,
                 held.empty() ? 0.0 : *std::max_element(options.maxDisplacement.begin(), options.maxDisplacement.end()));
}

} // namespace slicemesh

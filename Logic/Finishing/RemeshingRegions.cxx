#include "Finishing/RemeshingRegions.h"

#include "Core/AreaNormal.h"
#include "Core/DisjointSets.h"
#include "Measures/MeshComponents.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace slicemesh
{

std::vector<int> slabRegions(const TriangleMesh& mesh, std::size_t trianglesPerRegion, double minimumHeight, int& count)
{
  const std::size_t n = mesh.triangles.size();
  std::vector<double> height(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    height[t] = (mesh.points[tri[0]].z + mesh.points[tri[1]].z + mesh.points[tri[2]].z) / 3.0;
  }
  const std::size_t slabs = std::max<std::size_t>(1, trianglesPerRegion > 0 ? n / trianglesPerRegion : 1);
  std::vector<double> sorted = height;
  std::sort(sorted.begin(), sorted.end());
  // A cut closer than minimumHeight to the one before (or to the top) is skipped: where the surface
  // lies flat across the slices a quantile slab is thin, and the bands around its two seams would
  // meet and be remeshed as one large region on one thread.
  std::vector<double> cuts;
  const double bottom = n > 0 ? sorted.front() : 0.0, top = n > 0 ? sorted.back() : 0.0;
  for (std::size_t k = 1; k < slabs; ++k)
  {
    const double cut = sorted[k * n / slabs];
    const double previous = cuts.empty() ? bottom : cuts.back();
    if (cut > previous && cut - previous >= minimumHeight && top - cut >= minimumHeight)
      cuts.push_back(cut);
  }
  count = static_cast<int>(cuts.size()) + 1;
  std::vector<int> regionOf(n);
  for (std::size_t t = 0; t < n; ++t)
    regionOf[t] = static_cast<int>(std::upper_bound(cuts.begin(), cuts.end(), height[t]) - cuts.begin());
  return regionOf;
}

std::vector<std::size_t> mostWorkFirst(const TriangleMesh& mesh, const std::vector<int>& regionOf, int count,
                                       double targetEdgeLength)
{
  const double targetArea = 0.25 * std::sqrt(3.0) * targetEdgeLength * targetEdgeLength;
  std::vector<double> work(static_cast<std::size_t>(std::max(count, 0)), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (regionOf[t] >= 0)
    {
      const Point3 n = areaNormal(mesh, mesh.triangles[t]);
      const double targets = 0.5 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z) / targetArea;
      // A finite order whatever the points: the sort's comparison must stay a strict weak ordering.
      work[static_cast<std::size_t>(regionOf[t])] += 1.0 + (std::isfinite(targets) ? targets : 0.0);
    }
  std::vector<std::size_t> order(work.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
  return order;
}

namespace
{

/** Throws unless a region's list of triangle numbers (32 bits each) can name `triangles` of them. */
void checkListable(std::size_t triangles)
{
  if (triangles > std::numeric_limits<std::uint32_t>::max())
    throw Error("remeshing regions: more triangles than a region's list can name");
}

} // namespace

std::vector<char> seamVertices(const TriangleMesh& mesh, const std::vector<int>& regionOf)
{
  constexpr int none = -2;
  std::vector<int> first(mesh.points.size(), none);
  std::vector<char> seam(mesh.points.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::int32_t v : mesh.triangles[t])
    {
      int& seen = first[static_cast<std::size_t>(v)];
      if (seen == none)
        seen = regionOf[t];
      else if (seen != regionOf[t])
        seam[static_cast<std::size_t>(v)] = 1;
    }
  return seam;
}

std::vector<int> seamBands(const TriangleMesh& mesh, const std::vector<char>& seam, int rings, int& count)
{
  checkListable(mesh.triangles.size());
  std::vector<char> near = seam;
  growByRings(mesh, near, rings);
  // The band's triangles in mesh order, each known below by its place in this list: the sets and
  // lists below are as large as the band, not as the piece (a third of the piece on the scaling
  // ellipsoid, whose band pass ran on one thread while the other waited).
  std::vector<std::uint32_t> band;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    if (near[tri[0]] || near[tri[1]] || near[tri[2]])
      band.push_back(static_cast<std::uint32_t>(t));
  }
  // Band triangles joined by their edges: each edge's other triangle is found among the band
  // triangles around one of its ends (a vertex has a few), not by sorting every band edge (half the
  // triangles of a piece in slabs: on the thick scaling ellipsoid that sort was 60 ms on one thread).
  std::vector<std::size_t> firstAround(mesh.points.size() + 1, 0);
  for (std::uint32_t t : band)
    for (std::int32_t v : mesh.triangles[t])
      ++firstAround[static_cast<std::size_t>(v) + 1];
  std::partial_sum(firstAround.begin(), firstAround.end(), firstAround.begin());
  std::vector<std::uint32_t> around(firstAround.back()); // places in `band`
  {
    std::vector<std::size_t> next(firstAround.begin(), firstAround.end() - 1);
    for (std::size_t b = 0; b < band.size(); ++b)
      for (std::int32_t v : mesh.triangles[band[b]])
        around[next[static_cast<std::size_t>(v)]++] = static_cast<std::uint32_t>(b);
  }
  // A triangle holds edge ab (a != b) if it holds both ends, and a collapsed edge aa if it holds a
  // twice; its candidates are the band triangles around the end with fewer of them. Each pair is
  // joined once, from its earlier triangle.
  auto occurrences = [](const Triangle& tri, std::int32_t v) { return (tri[0] == v) + (tri[1] == v) + (tri[2] == v); };
  auto aroundOf = [&](std::int32_t v)
  { return firstAround[static_cast<std::size_t>(v) + 1] - firstAround[static_cast<std::size_t>(v)]; };
  DisjointSets sets(band.size());
  for (std::size_t b = 0; b < band.size(); ++b)
  {
    const Triangle& tri = mesh.triangles[band[b]];
    for (int corner = 0; corner < 3; ++corner)
    {
      std::int32_t u = tri[corner], w = tri[(corner + 1) % 3];
      if (aroundOf(w) < aroundOf(u))
        std::swap(u, w);
      const auto v = static_cast<std::size_t>(u);
      for (std::size_t i = firstAround[v]; i < firstAround[v + 1]; ++i)
      {
        if (around[i] <= b)
          continue;
        const Triangle& other = mesh.triangles[band[around[i]]];
        if (u != w ? occurrences(other, w) > 0 : occurrences(other, u) > 1)
          sets.unite(b, around[i]);
      }
    }
  }
  // Numbered in the order of their first triangle: roots are the smallest members (DisjointSets),
  // so a set's number is given at its root.
  std::vector<int> regionOf(mesh.triangles.size(), -1), numberOf(band.size(), -1);
  count = 0;
  for (std::size_t b = 0; b < band.size(); ++b)
  {
    const std::size_t root = sets.find(b);
    if (root == b)
      numberOf[b] = count++;
    regionOf[band[b]] = numberOf[root];
  }
  return regionOf;
}

RegionTriangles trianglesByRegion(const std::vector<int>& regionOf, int count)
{
  checkListable(regionOf.size());
  RegionTriangles regions;
  regions.first.assign(static_cast<std::size_t>(std::max(count, 0)) + 1, 0);
  for (int r : regionOf)
    if (r >= 0)
      ++regions.first[static_cast<std::size_t>(r) + 1];
  std::partial_sum(regions.first.begin(), regions.first.end(), regions.first.begin());
  regions.ids.resize(regions.first.back());
  std::vector<std::size_t> next(regions.first.begin(), regions.first.end() - 1);
  for (std::size_t t = 0; t < regionOf.size(); ++t)
    if (regionOf[t] >= 0)
      regions.ids[next[static_cast<std::size_t>(regionOf[t])]++] = static_cast<std::uint32_t>(t);
  return regions;
}

MeshRegion extractRegion(const TriangleMesh& mesh, const std::uint32_t* begin, const std::uint32_t* end)
{
  MeshRegion result;
  result.mesh.triangles.reserve(static_cast<std::size_t>(end - begin));
  // Each mesh vertex's number in the region plus one (0: not in it yet).
  std::vector<std::int32_t> local(mesh.points.size());
  for (const std::uint32_t* t = begin; t != end; ++t)
  {
    Triangle tri{};
    for (int corner = 0; corner < 3; ++corner)
    {
      const std::int32_t v = mesh.triangles[*t][corner];
      std::int32_t& id = local[static_cast<std::size_t>(v)];
      if (id == 0)
      {
        result.mesh.points.push_back(mesh.points[static_cast<std::size_t>(v)]);
        result.origin.push_back(v);
        id = static_cast<std::int32_t>(result.mesh.points.size());
      }
      tri[corner] = id - 1;
    }
    result.mesh.triangles.push_back(tri);
  }
  return result;
}

MeshRegion extractRegion(const TriangleMesh& mesh, const std::vector<int>& regionOf, int region)
{
  checkListable(mesh.triangles.size());
  std::vector<std::uint32_t> triangles;
  triangles.reserve(static_cast<std::size_t>(std::count(regionOf.begin(), regionOf.end(), region)));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (regionOf[t] == region)
      triangles.push_back(static_cast<std::uint32_t>(t));
  return extractRegion(mesh, triangles.data(), triangles.data() + triangles.size());
}

TriangleMesh reassembleRegions(const TriangleMesh& mesh, const std::vector<int>& regionOf,
                               const std::vector<MeshRegion>& regions)
{
  // Sized up front: vectors grown one element at a time hold up to twice their size, and the
  // reassembled piece is among the largest things a run holds.
  std::size_t points = mesh.points.size(), triangles = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    triangles += regionOf[t] < 0;
  for (const MeshRegion& region : regions)
  {
    points += static_cast<std::size_t>(
      std::count_if(region.origin.begin(), region.origin.end(), [](std::int32_t o) { return o < 0; }));
    triangles += region.mesh.triangles.size();
  }
  TriangleMesh result;
  result.points.reserve(points);
  result.points.assign(mesh.points.begin(), mesh.points.end());
  result.triangles.reserve(triangles);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (regionOf[t] < 0)
      result.triangles.push_back(mesh.triangles[t]);
  for (const MeshRegion& region : regions)
  {
    std::vector<std::int32_t> global(region.mesh.points.size());
    for (std::size_t v = 0; v < region.mesh.points.size(); ++v)
    {
      if (region.origin[v] >= 0)
      {
        global[v] = region.origin[v];
        result.points[static_cast<std::size_t>(region.origin[v])] = region.mesh.points[v];
      }
      else
      {
        global[v] = static_cast<std::int32_t>(result.points.size());
        result.points.push_back(region.mesh.points[v]);
      }
    }
    for (const Triangle& t : region.mesh.triangles)
      result.triangles.push_back({ global[t[0]], global[t[1]], global[t[2]] });
  }
  return result;
}

TriangleMesh withoutUnusedVertices(const TriangleMesh& mesh)
{
  std::vector<std::int32_t> index(mesh.points.size(), -1);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t)
      index[static_cast<std::size_t>(v)] = 0;
  TriangleMesh result;
  result.points.reserve(static_cast<std::size_t>(std::count(index.begin(), index.end(), 0)));
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (index[v] == 0)
    {
      index[v] = static_cast<std::int32_t>(result.points.size());
      result.points.push_back(mesh.points[v]);
    }
  result.triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    result.triangles.push_back({ index[t[0]], index[t[1]], index[t[2]] });
  return result;
}

} // namespace slicemesh

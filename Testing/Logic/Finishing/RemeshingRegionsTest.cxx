// The bands around slab seams against their definition, checked pair by pair: the triangles within
// `rings` rings of a seam vertex, one region per set of them joined by common edges, numbered in the
// order of their first triangle.
#include "Finishing/RemeshingRegions.h"

#include "Core/DisjointSets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

using namespace slicemesh;

namespace
{

std::set<std::pair<std::int32_t, std::int32_t>> edgesOf(const Triangle& t)
{
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (int corner = 0; corner < 3; ++corner)
    edges.insert({ std::min(t[corner], t[(corner + 1) % 3]), std::max(t[corner], t[(corner + 1) % 3]) });
  return edges;
}

/** The bands by their definition, every pair of triangles compared. */
std::vector<int> bandsByDefinition(const TriangleMesh& mesh, std::vector<char> near, int rings, int& count)
{
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> grown = near;
    for (const Triangle& t : mesh.triangles)
      if (near[t[0]] || near[t[1]] || near[t[2]])
        for (std::int32_t v : t)
          grown[v] = 1;
    near.swap(grown);
  }
  const std::size_t n = mesh.triangles.size();
  std::vector<char> inBand(n);
  for (std::size_t t = 0; t < n; ++t)
    inBand[t] = near[mesh.triangles[t][0]] || near[mesh.triangles[t][1]] || near[mesh.triangles[t][2]];
  DisjointSets sets(n);
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t t = s + 1; t < n; ++t)
    {
      if (!inBand[s] || !inBand[t])
        continue;
      const auto a = edgesOf(mesh.triangles[s]), b = edgesOf(mesh.triangles[t]);
      if (std::any_of(a.begin(), a.end(), [&b](const auto& e) { return b.count(e) > 0; }))
        sets.unite(s, t);
    }
  std::vector<int> regionOf(n, -1), numberOfRoot(n, -1);
  count = 0;
  for (std::size_t t = 0; t < n; ++t)
    if (inBand[t])
    {
      int& number = numberOfRoot[sets.find(t)];
      if (number < 0)
        number = count++;
      regionOf[t] = number;
    }
  return regionOf;
}

} // namespace

TEST(SeamBands, TriangleWithARepeatedCornerJoinsOnlyAlongARealEdge)
{
  // {0, 0, 3} touches {0, 1, 2} at vertex 0 only: two regions.
  TriangleMesh mesh;
  mesh.points.resize(4);
  mesh.triangles = { { 0, 1, 2 }, { 0, 0, 3 } };
  int count = 0;
  EXPECT_EQ(seamBands(mesh, std::vector<char>(4, 1), 0, count), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(count, 2);
}

TEST(SeamBands, MatchTheirDefinitionOnRandomMeshes)
{
  // Small random meshes with edges shared by three triangles, repeated triangles and triangles with
  // repeated corners among them.
  std::mt19937 random(7);
  for (int trial = 0; trial < 3000; ++trial)
  {
    const int vertices = 3 + static_cast<int>(random() % 12), triangles = 1 + static_cast<int>(random() % 16);
    TriangleMesh mesh;
    mesh.points.resize(static_cast<std::size_t>(vertices));
    for (int t = 0; t < triangles; ++t)
    {
      Triangle tri{};
      for (std::int32_t& v : tri)
        v = static_cast<std::int32_t>(random() % static_cast<unsigned>(vertices));
      mesh.triangles.push_back(tri);
    }
    std::vector<char> seam(static_cast<std::size_t>(vertices));
    for (char& c : seam)
      c = random() % 4 == 0;
    const int rings = static_cast<int>(random() % 3);
    int count = 0, expectedCount = 0;
    const std::vector<int> regions = seamBands(mesh, seam, rings, count);
    const std::vector<int> expected = bandsByDefinition(mesh, seam, rings, expectedCount);
    ASSERT_EQ(regions, expected) << "trial " << trial;
    ASSERT_EQ(count, expectedCount) << "trial " << trial;
  }
}

TEST(RegionOrder, MostWorkFirstCountsTheAreaToFillAsWellAsTheTriangles)
{
  // Region 1 is two triangles of 50 target triangles' area each (a cap tiled with a few large
  // triangles); regions 0 and 2 are ten small triangles each, region 3 twelve; region 4 is empty and
  // region -1 is left alone (not counted). By triangles alone region 1 would come last.
  const double edge = 1.0;
  // A right triangle of legs s has area s^2 / 2: 2 * 50 * sqrt(3) / 4 * edge^2 when s^2 is that.
  const double side = std::sqrt(25.0 * std::sqrt(3.0)) * edge;
  TriangleMesh mesh;
  auto addTriangle = [&mesh](double x, double y, double size, int z)
  {
    const auto first = static_cast<std::int32_t>(mesh.points.size());
    mesh.points.push_back({ x, y, static_cast<double>(z) });
    mesh.points.push_back({ x + size, y, static_cast<double>(z) });
    mesh.points.push_back({ x, y + size, static_cast<double>(z) });
    mesh.triangles.push_back({ first, first + 1, first + 2 });
  };
  std::vector<int> regionOf;
  auto add = [&](int region, int count, double size)
  {
    for (int i = 0; i < count; ++i)
    {
      addTriangle(i, 0.0, size, region);
      regionOf.push_back(region);
    }
  };
  add(0, 10, 0.1 * edge);
  add(1, 2, side);
  add(2, 10, 0.1 * edge);
  add(3, 12, 0.1 * edge);
  add(-1, 100, 10.0 * edge);
  EXPECT_EQ(mostWorkFirst(mesh, regionOf, 5, edge), (std::vector<std::size_t>{ 1, 3, 0, 2, 4 }));
}

TEST(RegionTriangles, EachRegionCutOutFromItsListIsItsTrianglesNumberedByFirstAppearance)
{
  // Random meshes and regions (some triangles in none, some regions empty): every region cut out from
  // its list holds the mesh's triangles of that region in mesh order, each corner mapped through
  // `origin` to the mesh's own, its points the mesh's, and its vertices numbered as they first appear.
  std::mt19937 random(11);
  for (int trial = 0; trial < 500; ++trial)
  {
    const int vertices = 3 + static_cast<int>(random() % 40), triangles = static_cast<int>(random() % 60);
    const int count = 1 + static_cast<int>(random() % 5);
    TriangleMesh mesh;
    for (int v = 0; v < vertices; ++v)
      mesh.points.push_back({ double(v), double(v % 7), double(v % 3) });
    std::vector<int> regionOf;
    for (int t = 0; t < triangles; ++t)
    {
      Triangle tri{};
      for (std::int32_t& v : tri)
        v = static_cast<std::int32_t>(random() % static_cast<unsigned>(vertices));
      mesh.triangles.push_back(tri);
      regionOf.push_back(static_cast<int>(random() % static_cast<unsigned>(count + 1)) - 1);
    }
    const RegionTriangles byRegion = trianglesByRegion(regionOf, count);
    ASSERT_EQ(byRegion.first.size(), static_cast<std::size_t>(count) + 1);
    for (int r = 0; r < count; ++r)
    {
      const MeshRegion region = extractRegion(mesh, byRegion.ids.data() + byRegion.first[r],
                                              byRegion.ids.data() + byRegion.first[r + 1]);
      std::vector<std::size_t> expected;
      for (std::size_t t = 0; t < regionOf.size(); ++t)
        if (regionOf[t] == r)
          expected.push_back(t);
      ASSERT_EQ(region.mesh.triangles.size(), expected.size()) << "trial " << trial << " region " << r;
      ASSERT_EQ(region.origin.size(), region.mesh.points.size());
      std::int32_t next = 0; // the next new vertex's number, in order of first appearance
      for (std::size_t k = 0; k < expected.size(); ++k)
        for (int corner = 0; corner < 3; ++corner)
        {
          const std::int32_t local = region.mesh.triangles[k][corner];
          ASSERT_LE(local, next);
          if (local == next)
            ++next;
          ASSERT_EQ(region.origin[static_cast<std::size_t>(local)], mesh.triangles[expected[k]][corner]);
          const Point3& p = region.mesh.points[static_cast<std::size_t>(local)];
          const Point3& q = mesh.points[static_cast<std::size_t>(mesh.triangles[expected[k]][corner])];
          ASSERT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z);
        }
      ASSERT_EQ(static_cast<std::size_t>(next), region.mesh.points.size());
      // One vertex of the region for each of the mesh's: no mesh vertex twice.
      std::vector<std::int32_t> origins = region.origin;
      std::sort(origins.begin(), origins.end());
      ASSERT_TRUE(std::adjacent_find(origins.begin(), origins.end()) == origins.end()) << "trial " << trial;
      // The whole-mesh form gives the same region.
      const MeshRegion scanned = extractRegion(mesh, regionOf, r);
      ASSERT_EQ(scanned.origin, region.origin);
      ASSERT_EQ(scanned.mesh.triangles, region.mesh.triangles);
    }
  }
}

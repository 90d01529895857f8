// The project's self-intersection test (selfIntersectingTrianglePairs, what validateMesh counts)
// against CGAL's own (Polygon_mesh_processing::self_intersections) on the meshes the pipeline makes:
// the property test's random masks and the benchmark's phantoms, each as tiled, as finished, and
// crumpled (every vertex moved at random by up to a voxel, so that it crosses itself in many ways:
// across shared edges, at shared corners, between triangles far apart in the mesh). The two must
// report the same pairs exactly.
#include "BenchmarkPhantoms.h"
#include "PhantomGrid.h"
#include "PropertySeeds.h"
#include "ReliabilitySupport.h"
#include "Measures/SelfIntersections.h"
#include "Measures/SurfaceMeshConversion.h"

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace slicemesh::testing
{
namespace
{

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

/** CGAL's pairs for the mesh, by triangle index, sorted; false when CGAL cannot hold it as a surface. */
bool cgalPairs(const TriangleMesh& mesh, Pairs& pairs)
{
  CgalSurfaceMesh surface;
  if (toSurfaceMesh(mesh, surface) != mesh.triangles.size())
    return false;
  std::vector<std::pair<CgalSurfaceMesh::Face_index, CgalSurfaceMesh::Face_index>> faces;
  CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(faces));
  pairs.clear();
  for (const auto& [f, g] : faces)
    pairs.emplace_back(std::min<std::size_t>(f.idx(), g.idx()), std::max<std::size_t>(f.idx(), g.idx()));
  std::sort(pairs.begin(), pairs.end());
  return true;
}

/** The mesh with every vertex moved by up to `reach` along each axis (seeded). */
TriangleMesh crumpled(TriangleMesh mesh, double reach, std::uint64_t seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> shift(-reach, reach);
  for (Point3& p : mesh.points)
    p = { p.x + shift(random), p.y + shift(random), p.z + shift(random) };
  return mesh;
}

struct Agreement
{
  std::size_t meshes = 0;
  std::size_t pairs = 0; ///< crossing pairs both found
  std::size_t degenerate = 0;
};

/** Compares the two tests on `mesh`; adds what was compared to `tally`. */
void expectAgreement(const TriangleMesh& mesh, const std::string& what, Agreement& tally)
{
  Pairs expected;
  if (!cgalPairs(mesh, expected))
    return; // not a manifold surface: neither validateMesh nor CGAL tests it
  const Pairs found = selfIntersectingTrianglePairs(mesh);
  EXPECT_EQ(found, expected) << what << ": " << found.size() << " pairs found, CGAL finds " << expected.size();
  EXPECT_EQ(selfIntersectingTrianglePairs(mesh, 1), found) << what << ": one thread finds other pairs";
  ++tally.meshes;
  tally.pairs += expected.size();
  tally.degenerate += static_cast<std::size_t>(
    std::count_if(expected.begin(), expected.end(), [](const auto& pair) { return pair.first == pair.second; }));
}

/** The tiling, the finished surface and a crumpled copy of each. */
void compareAllForms(const MaskMeshResult& run, double voxel, std::uint64_t seed, const std::string& what,
                     Agreement& tally)
{
  expectAgreement(run.meshing.tiling, what + " (tiled)", tally);
  expectAgreement(run.meshing.surface.mesh, what + " (finished)", tally);
  expectAgreement(crumpled(run.meshing.tiling, voxel, seed), what + " (tiled, crumpled)", tally);
  expectAgreement(crumpled(run.meshing.surface.mesh, 0.5 * voxel, seed + 1), what + " (finished, crumpled)", tally);
}

} // namespace

TEST(SelfIntersectionAgreement, SameCrossingPairsAsCgalOnRandomMasks)
{
  Agreement tally;
  for (const RandomMaskKind kind : { RandomMaskKind::Any, RandomMaskKind::ThresholdedMri })
  {
    const auto [begin, end] = propertySeeds(kind == RandomMaskKind::Any ? 9100 : 9200, 10);
    for (std::uint64_t seed = begin; seed < end; ++seed)
    {
      const RandomMask random = randomMask(seed, kind);
      MeshingOptions meshing;
      meshing.reconstruction = random.options;
      const MaskMeshResult run = checkedMesh(random.mask, meshing);
      if (run.contours == 0 || !run.error.empty())
        continue;
      const auto spacing = random.mask->GetSpacing();
      compareAllForms(run, std::min({ spacing[0], spacing[1], spacing[2] }), seed, random.description, tally);
    }
  }
  std::cout << "[ agreement ] random masks: " << tally.meshes << " meshes, " << tally.pairs << " crossing pairs ("
            << tally.degenerate << " degenerate triangles)\n";
  EXPECT_GE(tally.meshes, 40u);
  EXPECT_GT(tally.pairs, 1000u) << "the crumpled meshes must cross themselves for the comparison to mean anything";
}

TEST(SelfIntersectionAgreement, SameCrossingPairsAsCgalOnTheBenchmarkPhantoms)
{
  Agreement tally;
  std::uint64_t seed = 1;
  for (const NamedPhantom& named : benchmarkPhantoms())
  {
    const std::array<double, 3> spacing{ 1.0, 1.0, 2.0 };
    const MaskVolume::Pointer mask = rasterizePhantom(*named.phantom, gridAround(*named.phantom, spacing));
    const MaskMeshResult run = checkedMesh(mask.GetPointer(), MeshingOptions{});
    ASSERT_TRUE(run.error.empty()) << named.name << ": " << run.error;
    compareAllForms(run, 1.0, ++seed, named.name, tally);
  }
  std::cout << "[ agreement ] phantoms: " << tally.meshes << " meshes, " << tally.pairs << " crossing pairs\n";
  EXPECT_EQ(tally.meshes, 4 * benchmarkPhantoms().size());
  EXPECT_GT(tally.pairs, 1000u);
}

} // namespace slicemesh::testing

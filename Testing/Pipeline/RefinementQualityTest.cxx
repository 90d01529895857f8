// Issue 4, item 5: with Steiner refinement on, on every phantom and grid, fewer than 1% of the
// triangles have an angle under 30 degrees, the smallest angle is at least the bound the method
// states, the mesh is still valid (closed, manifold, no self-intersections), and its distance to
// the exact surface is no worse than without refinement.
//
// DISABLED_ until the refinement algorithm (Logic/SlabTiling.cxx) meets them: enable by removing
// the prefix. Run them now with --gtest_also_run_disabled_tests to see the figures.
#include "Box.h"
#include "CappedCylinder.h"
#include "Ellipsoid.h"
#include "MeshQuality.h"
#include "PhantomMeshing.h"
#include "Sphere.h"
#include "Torus.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** The smallest angle the refinement promises (degrees). Ruppert/Shewchuk refinement with CGAL's
 *  default shape bound guarantees 20.7 degrees in 2D; the lead states the 3D bound of the method. */
constexpr double statedMinAngleBound = 20.0;

struct Grid
{
  const char* name;
  std::array<double, 3> spacing;
};

void expectRefinedQuality(const char* name, const Phantom& phantom)
{
  for (const Grid& grid : { Grid{ "iso1mm", { 1.0, 1.0, 1.0 } }, Grid{ "aniso08x08x3", { 0.8, 0.8, 3.0 } } })
  {
    SCOPED_TRACE(std::string(name) + " " + grid.name);
    ReconstructionOptions refined; // minAngleDegrees = 30 by default
    ReconstructionOptions plain;
    plain.minAngleDegrees = 0.0;
    const PhantomMeshResult on = meshPhantom(phantom, grid.spacing, Matrix3::Identity(), refined);
    const PhantomMeshResult off = meshPhantom(phantom, grid.spacing, Matrix3::Identity(), plain);
    const MeshQuality q = measureMeshQuality(on.mesh);
    std::printf("%-10s %-13s refined: %zu triangles, <30deg %.2f%%, min angle %.2f, surface distance %.3f mm "
                "(unrefined %.3f), %s\n",
                name, grid.name, q.triangles, 100.0 * q.fractionBelow30, q.minAngleDegrees, on.surfaceDistance,
                off.surfaceDistance, on.validation.valid() ? "valid" : on.validation.summary().c_str());
    EXPECT_LT(q.fractionBelow30, 0.01);
    EXPECT_GE(q.minAngleDegrees, statedMinAngleBound);
    EXPECT_TRUE(on.validation.valid()) << on.validation.summary();
    // The surface, not only its vertices: refinement adds vertices inside the slabs, which a mean
    // over vertices would weigh against the unrefined mesh's contour vertices alone.
    EXPECT_LE(on.surfaceDistance, off.surfaceDistance * 1.001);
  }
}

} // namespace

TEST(RefinementQuality, DISABLED_Sphere)
{
  expectRefinedQuality("sphere", Sphere({ 1.0, -2.0, 3.0 }, 20.0));
}

TEST(RefinementQuality, DISABLED_RotatedEllipsoid)
{
  expectRefinedQuality("ellipsoid", Ellipsoid({ 1, 2, 3 }, { 25, 15, 10 }, rotation({ 1, 2, 3 }, 0.7)));
}

TEST(RefinementQuality, DISABLED_TiltedCylinder)
{
  expectRefinedQuality("cylinder", CappedCylinder({ 0, 0, 0 }, { 0.3, 0.2, 1.0 }, 10.0, 20.0));
}

TEST(RefinementQuality, DISABLED_RotatedBox)
{
  expectRefinedQuality("box", Box({ 0, 0, 0 }, { 15, 10, 8 }, rotation({ 0, 1, 1 }, 0.5)));
}

TEST(RefinementQuality, DISABLED_Torus)
{
  expectRefinedQuality("torus", Torus({ 0, 0, 0 }, { 1, 0, 0.5 }, 18.0, 6.0));
}

// A guard on what the refinement reaches today, so it cannot slip back while the targets above are
// still open: valid meshes on every phantom, at most 2% of triangles under 30 degrees on both grids
// (measured 0.0-1.2% at 1 mm, 0.5-1.8% at 0.8 x 0.8 x 3 mm), and the surface no farther from the
// exact one than the unrefined tiling's by more than 10% (measured -11% to +7%).
TEST(RefinementQuality, GuardOnTodaysFigures)
{
  const std::vector<std::pair<const char*, std::shared_ptr<const Phantom>>> phantoms = {
    { "sphere", std::make_shared<Sphere>(Vector3{ 1.0, -2.0, 3.0 }, 20.0) },
    { "ellipsoid", std::make_shared<Ellipsoid>(Vector3{ 1, 2, 3 }, Vector3{ 25, 15, 10 }, rotation({ 1, 2, 3 }, 0.7)) },
    { "cylinder", std::make_shared<CappedCylinder>(Vector3{ 0, 0, 0 }, Vector3{ 0.3, 0.2, 1.0 }, 10.0, 20.0) },
    { "box", std::make_shared<Box>(Vector3{ 0, 0, 0 }, Vector3{ 15, 10, 8 }, rotation({ 0, 1, 1 }, 0.5)) },
    { "torus", std::make_shared<Torus>(Vector3{ 0, 0, 0 }, Vector3{ 1, 0, 0.5 }, 18.0, 6.0) }
  };
  for (const auto& [name, phantom] : phantoms)
    for (const Grid& grid : { Grid{ "iso1mm", { 1.0, 1.0, 1.0 } }, Grid{ "aniso08x08x3", { 0.8, 0.8, 3.0 } } })
    {
      SCOPED_TRACE(std::string(name) + " " + grid.name);
      ReconstructionOptions plain;
      plain.minAngleDegrees = 0.0;
      const PhantomMeshResult on = meshPhantom(*phantom, grid.spacing);
      const PhantomMeshResult off = meshPhantom(*phantom, grid.spacing, Matrix3::Identity(), plain);
      const MeshQuality q = measureMeshQuality(on.mesh);
      EXPECT_TRUE(on.validation.valid()) << on.validation.summary();
      EXPECT_LE(q.fractionBelow30, 0.02);
      EXPECT_LE(on.surfaceDistance, off.surfaceDistance * 1.10);
    }
}

#include "Box.h"
#include "CappedCylinder.h"
#include "Ellipsoid.h"
#include "PhantomCombinators.h"
#include "PhantomGrid.h"
#include "Sphere.h"
#include "Torus.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slicemesh
{
namespace
{

double maskVolume(const MaskVolume* mask)
{
  const auto& spacing = mask->GetSpacing();
  std::size_t count = 0;
  const unsigned char* voxel = mask->GetBufferPointer();
  for (std::size_t n = 0; n < mask->GetBufferedRegion().GetNumberOfPixels(); ++n)
    count += voxel[n] != 0;
  return count * spacing[0] * spacing[1] * spacing[2];
}

/** No voxel in the outer `layers` layers of the grid is inside. */
bool borderIsEmpty(const MaskVolume* mask, std::size_t layers)
{
  const auto size = mask->GetBufferedRegion().GetSize();
  for (std::size_t k = 0; k < size[2]; ++k)
    for (std::size_t j = 0; j < size[1]; ++j)
      for (std::size_t i = 0; i < size[0]; ++i)
      {
        const bool border = i < layers || j < layers || k < layers || i >= size[0] - layers ||
                            j >= size[1] - layers || k >= size[2] - layers;
        if (border && mask->GetPixel({ { long(i), long(j), long(k) } }))
          return false;
      }
  return true;
}

const Matrix3 someRotation =
  (Eigen::AngleAxisd(0.4, Vector3::UnitZ()) * Eigen::AngleAxisd(-0.7, Vector3(1, 1, 0).normalized())).toRotationMatrix();

TEST(Phantom, SphereRasterVolumeIsWithinThreePercent)
{
  const Sphere sphere(Vector3(1.3, -2.2, 0.4), 10.0);
  MaskVolume::Pointer mask = rasterizePhantom(sphere, gridAround(sphere, { 1.0, 1.0, 1.0 }));
  const double exact = 4.0 / 3.0 * M_PI * 1000.0;
  EXPECT_DOUBLE_EQ(sphere.volume(), exact);
  EXPECT_NEAR(maskVolume(mask), exact, 0.03 * exact);
  EXPECT_TRUE(borderIsEmpty(mask, 2));
}

TEST(Phantom, SphereDistanceIsExact)
{
  const Sphere sphere(Vector3(1.0, 2.0, 3.0), 5.0);
  EXPECT_DOUBLE_EQ(sphere.signedDistance(Vector3(1.0, 2.0, 3.0)), -5.0);
  EXPECT_DOUBLE_EQ(sphere.signedDistance(Vector3(1.0, 2.0, 11.0)), 3.0);
  EXPECT_DOUBLE_EQ(sphere.signedDistance(Vector3(4.0, 6.0, 3.0)), 0.0);
  EXPECT_DOUBLE_EQ(distanceToSurface(sphere, Point3{ 1.0, 2.0, 5.0 }), 3.0);
}

TEST(Phantom, BoxDistanceIsExact)
{
  const Box box(Vector3::Zero(), Vector3(1.0, 2.0, 3.0));
  EXPECT_DOUBLE_EQ(box.signedDistance(Vector3::Zero()), -1.0);
  EXPECT_DOUBLE_EQ(box.signedDistance(Vector3(0.0, 0.0, 5.0)), 2.0);
  EXPECT_DOUBLE_EQ(box.signedDistance(Vector3(4.0, 6.0, 0.0)), 5.0); // beyond an edge: (3, 4)
  EXPECT_DOUBLE_EQ(box.volume(), 48.0);

  const Box rotated(Vector3(1.0, 1.0, 1.0), Vector3(1.0, 2.0, 3.0), someRotation);
  const Vector3 cornerDirection = someRotation * Vector3(1.0, 1.0, 1.0).normalized();
  const Vector3 corner = Vector3(1.0, 1.0, 1.0) + someRotation * Vector3(1.0, 2.0, 3.0);
  EXPECT_NEAR(rotated.signedDistance(corner + 2.0 * cornerDirection), 2.0, 1e-12);
  const Bounds bounds = rotated.bounds();
  EXPECT_TRUE((corner.array() <= bounds.upper.array() + 1e-12).all());
}

TEST(Phantom, CappedCylinderDistanceIsExact)
{
  const CappedCylinder cylinder(Vector3(0.0, 0.0, 1.0), Vector3(0.0, 0.0, 2.0), 2.0, 3.0);
  EXPECT_DOUBLE_EQ(cylinder.signedDistance(Vector3(0.0, 0.0, 1.0)), -2.0);
  EXPECT_DOUBLE_EQ(cylinder.signedDistance(Vector3(0.0, 0.0, 6.0)), 2.0);  // above the top cap
  EXPECT_DOUBLE_EQ(cylinder.signedDistance(Vector3(5.0, 0.0, 1.0)), 3.0);  // beside the wall
  EXPECT_DOUBLE_EQ(cylinder.signedDistance(Vector3(0.0, 5.0, 8.0)), 5.0);  // beyond the rim: (3, 4)
  EXPECT_DOUBLE_EQ(cylinder.signedDistance(Vector3(0.0, 1.5, 3.5)), -0.5); // nearer the cap than the wall
  EXPECT_DOUBLE_EQ(cylinder.volume(), M_PI * 4.0 * 6.0);
  const Bounds bounds = cylinder.bounds();
  EXPECT_DOUBLE_EQ(bounds.lower[2], -2.0);
  EXPECT_DOUBLE_EQ(bounds.upper[0], 2.0);
}

TEST(Phantom, TorusDistanceIsExact)
{
  const Torus torus(Vector3::Zero(), Vector3(0.0, 0.0, 1.0), 5.0, 1.0);
  EXPECT_DOUBLE_EQ(torus.signedDistance(Vector3(5.0, 0.0, 0.0)), -1.0);
  EXPECT_DOUBLE_EQ(torus.signedDistance(Vector3::Zero()), 4.0); // the hole's centre
  EXPECT_DOUBLE_EQ(torus.signedDistance(Vector3(0.0, 8.0, 4.0)), 4.0);
  EXPECT_DOUBLE_EQ(torus.volume(), 2.0 * M_PI * M_PI * 5.0);
}

TEST(Phantom, EllipsoidWithEqualRadiiIsASphere)
{
  const Ellipsoid ellipsoid(Vector3(1.0, 2.0, 3.0), Vector3(4.0, 4.0, 4.0), someRotation);
  const Sphere sphere(Vector3(1.0, 2.0, 3.0), 4.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  for (int n = 0; n < 200; ++n)
  {
    const Vector3 point(coordinate(random), coordinate(random), coordinate(random));
    EXPECT_NEAR(ellipsoid.signedDistance(point), sphere.signedDistance(point), 1e-9);
  }
  EXPECT_NEAR(ellipsoid.signedDistance(Vector3(1.0, 2.0, 3.0)), -4.0, 1e-12);
}

TEST(Phantom, EllipsoidDistanceIsExactAlongNormals)
{
  // A point moved from the surface along the normal by d is at distance d: always outside (the
  // shape is convex), and inside while d stays below the smallest radius of curvature c^2 / a.
  const Vector3 radii(9.0, 5.0, 3.0);
  const Vector3 center(2.0, -1.0, 4.0);
  const Ellipsoid ellipsoid(center, radii, someRotation);
  const double smallestCurvatureRadius = 3.0 * 3.0 / 9.0;
  std::mt19937 random(11);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> outsideOffset(0.0, 30.0);
  std::uniform_real_distribution<double> insideOffset(0.0, 0.99 * smallestCurvatureRadius);
  for (int n = 0; n < 2000; ++n)
  {
    Vector3 direction(gaussian(random), gaussian(random), gaussian(random));
    if (n % 10 == 0)
      direction[n % 3] = 0.0; // points in the symmetry planes take other branches
    if (n % 50 == 0)
      direction = Vector3::Unit(n % 3);
    direction.normalize();
    const Vector3 localSurface = radii.cwiseProduct(direction);
    const Vector3 localNormal = direction.cwiseQuotient(radii).normalized();
    const Vector3 surface = center + someRotation * localSurface;
    const Vector3 normal = someRotation * localNormal;
    const double out = outsideOffset(random);
    const double in = insideOffset(random);
    EXPECT_NEAR(ellipsoid.signedDistance(surface + out * normal), out, 1e-9);
    EXPECT_NEAR(ellipsoid.signedDistance(surface - in * normal), -in, 1e-9);
  }
}

TEST(Phantom, EllipsoidDistanceOnTheMedialAxisIsNearestOfManySurfacePoints)
{
  // Deep inside, the nearest point is off the axis; compare with a dense search of the surface.
  const Vector3 radii(9.0, 5.0, 3.0);
  const Ellipsoid ellipsoid(Vector3::Zero(), radii);
  for (const Vector3 point : { Vector3(0.0, 0.0, 0.0), Vector3(4.0, 0.0, 0.0), Vector3(2.0, 1.0, 0.0), Vector3(0.0, 2.0, 0.0) })
  {
    double nearest = 1e9;
    const int steps = 1000;
    for (int a = 0; a <= steps; ++a)
      for (int b = 0; b < 2 * steps; b += 1)
      {
        const double theta = M_PI * a / steps, phi = M_PI * b / steps;
        const Vector3 surface(radii[0] * std::sin(theta) * std::cos(phi), radii[1] * std::sin(theta) * std::sin(phi),
                              radii[2] * std::cos(theta));
        nearest = std::min(nearest, (surface - point).norm());
      }
    const double distance = -ellipsoid.signedDistance(point);
    EXPECT_LE(distance, nearest + 1e-12) << point.transpose();
    EXPECT_NEAR(distance, nearest, 1e-3) << point.transpose();
  }
}

TEST(Phantom, RasterVolumesMatchExactVolumes)
{
  const std::vector<PhantomPointer> shapes = {
    std::make_shared<Ellipsoid>(Vector3(0.5, 0.0, 1.0), Vector3(12.0, 8.0, 6.0), someRotation),
    std::make_shared<Box>(Vector3::Zero(), Vector3(6.0, 9.0, 4.0), someRotation),
    std::make_shared<CappedCylinder>(Vector3::Zero(), Vector3(1.0, 2.0, 3.0), 5.0, 9.0),
    std::make_shared<Torus>(Vector3::Zero(), Vector3(0.0, 1.0, 1.0), 10.0, 3.0),
  };
  for (const PhantomPointer& shape : shapes)
  {
    const GridSpec grid = gridAround(*shape, { 0.5, 0.5, 0.5 });
    MaskVolume::Pointer mask = rasterizePhantom(*shape, grid);
    EXPECT_NEAR(maskVolume(mask), shape->volume(), 0.02 * shape->volume());
    EXPECT_TRUE(borderIsEmpty(mask, 2));
  }
}

TEST(Phantom, GridFollowsAnObliqueDirection)
{
  const Ellipsoid ellipsoid(Vector3(20.0, -10.0, 5.0), Vector3(10.0, 6.0, 15.0), someRotation);
  const Matrix3 oblique = Eigen::AngleAxisd(0.3, Vector3(0.2, 0.3, 1.0).normalized()).toRotationMatrix();
  const GridSpec grid = gridAround(ellipsoid, { 0.8, 0.8, 2.0 }, 2, oblique);
  MaskVolume::Pointer mask = rasterizePhantom(ellipsoid, grid);
  EXPECT_NEAR(maskVolume(mask), ellipsoid.volume(), 0.03 * ellipsoid.volume());
  EXPECT_TRUE(borderIsEmpty(mask, 2));
  // The image's own geometry agrees with the grid's.
  MaskVolume::IndexType index = { { 3, 4, 5 } };
  itk::Point<double, 3> physical;
  mask->TransformIndexToPhysicalPoint(index, physical);
  const Vector3 expected = grid.physicalPoint(3, 4, 5);
  for (int row = 0; row < 3; ++row)
    EXPECT_NEAR(physical[row], expected[row], 1e-9);
}

TEST(Phantom, CombinatorsCombineDistancesAndVolumes)
{
  auto outer = std::make_shared<Sphere>(Vector3::Zero(), 10.0);
  auto inner = std::make_shared<Sphere>(Vector3(1.0, 0.0, 0.0), 4.0);
  const NestedSubtraction shell(outer, inner);
  EXPECT_DOUBLE_EQ(shell.volume(), outer->volume() - inner->volume());
  EXPECT_DOUBLE_EQ(shell.signedDistance(Vector3(1.0, 0.0, 0.0)), 4.0);  // cavity centre
  EXPECT_DOUBLE_EQ(shell.signedDistance(Vector3(7.0, 0.0, 0.0)), -2.0); // in the wall
  EXPECT_DOUBLE_EQ(shell.signedDistance(Vector3(0.0, 12.0, 0.0)), 2.0); // outside

  auto other = std::make_shared<Sphere>(Vector3(25.0, 0.0, 0.0), 5.0);
  const DisjointUnion pair(outer, other);
  EXPECT_DOUBLE_EQ(pair.volume(), outer->volume() + other->volume());
  EXPECT_DOUBLE_EQ(pair.signedDistance(Vector3(15.0, 0.0, 0.0)), 5.0);
  EXPECT_DOUBLE_EQ(pair.signedDistance(Vector3(25.0, 0.0, 0.0)), -5.0);
  EXPECT_DOUBLE_EQ(pair.bounds().upper[0], 30.0);
  EXPECT_DOUBLE_EQ(pair.bounds().lower[0], -10.0);
}

TEST(Phantom, BadParametersAreRejected)
{
  EXPECT_THROW(Sphere(Vector3::Zero(), -1.0), std::invalid_argument);
  EXPECT_THROW(Torus(Vector3::Zero(), Vector3::UnitZ(), 1.0, 2.0), std::invalid_argument);
  EXPECT_THROW(CappedCylinder(Vector3::Zero(), Vector3::Zero(), 1.0, 2.0), std::invalid_argument);
  EXPECT_THROW(Box(Vector3::Zero(), Vector3::Ones(), 2.0 * Matrix3::Identity()), std::invalid_argument);
}

} // namespace
} // namespace slicemesh

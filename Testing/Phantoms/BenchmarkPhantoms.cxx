#include "BenchmarkPhantoms.h"

#include "Box.h"
#include "CappedCylinder.h"
#include "Ellipsoid.h"
#include "PhantomCombinators.h"
#include "Sphere.h"
#include "Torus.h"
#include "TubeTree.h"

#include <Eigen/Geometry>

namespace slicemesh
{
namespace
{

Matrix3 rotation(const Vector3& axis, double angle)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

} // namespace

std::vector<NamedPhantom> benchmarkPhantoms()
{
  return {
    { "sphere r20", std::make_shared<Sphere>(Vector3(0, 0, 0), 20.0) },
    { "ellipsoid 25x15x10 rotated", std::make_shared<Ellipsoid>(Vector3(1, 2, 3), Vector3(25, 15, 10), rotation({ 1, 2, 3 }, 0.7)) },
    { "cylinder r10 h40 tilted", std::make_shared<CappedCylinder>(Vector3(0, 0, 0), Vector3(0.3, 0.2, 1.0), 10.0, 20.0) },
    { "box 30x20x16 rotated", std::make_shared<Box>(Vector3(0, 0, 0), Vector3(15, 10, 8), rotation({ 0, 1, 1 }, 0.5)) },
    { "torus R18 r6", std::make_shared<Torus>(Vector3(0, 0, 0), Vector3(1, 0, 0.5), 18.0, 6.0) },
    { "hollow sphere r20/r10", std::make_shared<NestedSubtraction>(std::make_shared<Sphere>(Vector3(0, 0, 0), 20.0),
                                                                    std::make_shared<Sphere>(Vector3(0, 0, 0), 10.0)) },
    { "two spheres r10", std::make_shared<DisjointUnion>(std::make_shared<Sphere>(Vector3(-12, 0, 0), 10.0),
                                                          std::make_shared<Sphere>(Vector3(12, 0, 0), 10.0)) },
  };
}

NamedPhantom branchingTubes()
{
  return { "branching tubes r3", std::make_shared<TubeTree>(
                                   std::vector<TubeTree::Segment>{ { Vector3(0, 0, -20), Vector3(0, 0, 0) },
                                                                   { Vector3(0, 0, 0), Vector3(14, 4, 16) },
                                                                   { Vector3(0, 0, 0), Vector3(-12, -5, 18) } },
                                   3.0) };
}

NamedPhantom thinPlate()
{
  return { "thin plate 40x30x3 tilted", std::make_shared<Box>(Vector3(0, 0, 0), Vector3(20, 15, 1.5), rotation({ 1, 0, 0 }, 0.4)) };
}

std::vector<BenchmarkGrid> benchmarkGrids()
{
  return { { "1x1x1", { 1.0, 1.0, 1.0 } }, { "0.8x0.8x3", { 0.8, 0.8, 3.0 } } };
}

} // namespace slicemesh

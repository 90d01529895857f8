// The phantoms and grids of the quality benchmark, shared by the benchmark and the tool that writes
// them as mask files (to compare two builds' meshes of the same inputs).
#ifndef BenchmarkPhantoms_h
#define BenchmarkPhantoms_h

#include "Phantom.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace slicemesh
{

struct NamedPhantom
{
  std::string name; ///< "sphere r20"
  std::shared_ptr<const Phantom> phantom;
};

struct BenchmarkGrid
{
  std::string name;              ///< "1x1x1"
  std::array<double, 3> spacing; ///< mm
};

/** Sphere, rotated ellipsoid, tilted cylinder, rotated box, torus, hollow sphere, two spheres. */
std::vector<NamedPhantom> benchmarkPhantoms();

/** Shapes the quality table does not list, checked beside it: a trunk of tubes 6 mm across that
 *  branches in two, and a tilted plate 3 mm thick. */
NamedPhantom branchingTubes();
NamedPhantom thinPlate();

/** 1 x 1 x 1 mm and 0.8 x 0.8 x 3 mm. */
std::vector<BenchmarkGrid> benchmarkGrids();

} // namespace slicemesh

#endif

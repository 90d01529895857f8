// Writes the quality benchmark's phantoms, rasterized on its grids, as NRRD label maps named
// "<phantom>_<grid>.nrrd" (spaces as '-'), for Utilities/compare-builds.sh.
//
// Usage: WritePhantomMasks <output folder>
#include "BenchmarkPhantoms.h"
#include "MaskFileWriter.h"
#include "PhantomGrid.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

int main(int argc, char* argv[])
{
  using namespace slicemesh;
  if (argc != 2)
  {
    std::cerr << "Usage: " << argv[0] << " <output folder>\n";
    return 1;
  }
  std::filesystem::create_directories(argv[1]);
  for (const NamedPhantom& named : benchmarkPhantoms())
    for (const BenchmarkGrid& grid : benchmarkGrids())
    {
      std::string name = named.name + "_" + grid.name + ".nrrd";
      std::replace(name.begin(), name.end(), ' ', '-');
      std::replace(name.begin(), name.end(), '/', '-');
      const MaskVolume::Pointer mask = rasterizePhantom(*named.phantom, gridAround(*named.phantom, grid.spacing, 2));
      writeMaskFile(mask, (std::filesystem::path(argv[1]) / name).string());
    }
  return 0;
}

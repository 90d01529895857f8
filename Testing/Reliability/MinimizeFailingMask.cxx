// Shrinks a failing random mask of the property test to a minimal reproducer: removes voxels one at
// a time while the mesh still fails (any problem, or the same kind of problem with --same), then
// prints the mask as code to paste into a test.
//   MinimizeFailingMask <kind 0..4: blobs noise blobs+noise touching thin> <seed> [print]
#include "ReliabilitySupport.h"

#include <cstdlib>
#include <iostream>
#include <string>

using namespace slicemesh;
using namespace slicemesh::testing;

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: MinimizeFailingMask <kind 0..4> <seed>\n";
    return 2;
  }
  const auto kind = static_cast<RandomMaskKind>(std::atoi(argv[1]));
  const RandomMask random = randomMask(std::strtoull(argv[2], nullptr, 10), kind);
  MaskVolume::Pointer mask = random.mask;
  std::cout << random.description << "\n";
  if (argc > 3 && std::string(argv[3]) == "print")
  { // for a mask that hangs: print it as it is
    std::cout << maskAsCode(mask) << "\n";
    return 0;
  }
  auto fails = [&] {
    const MaskMeshResult r = checkedMesh(mask);
    return r.contours > 0 && !r.problem().empty();
  };
  if (!fails())
  {
    std::cout << "passes\n";
    return 0;
  }
  // The direction does not enter the stack frame; an identity one makes the reproducer simpler.
  MaskVolume::DirectionType identity;
  identity.SetIdentity();
  const MaskVolume::DirectionType original = mask->GetDirection();
  mask->SetDirection(identity);
  if (!fails())
    mask->SetDirection(original);
  unsigned char* voxel = mask->GetBufferPointer();
  const std::size_t count = mask->GetBufferedRegion().GetNumberOfPixels();
  for (bool changed = true; changed;)
  {
    changed = false;
    for (std::size_t v = 0; v < count; ++v)
      if (voxel[v])
      {
        voxel[v] = 0;
        mask->Modified();
        if (fails())
          changed = true;
        else
          voxel[v] = 1;
      }
  }
  const MaskMeshResult r = checkedMesh(mask);
  std::cout << r.problem() << "\n" << maskAsCode(mask) << "\n";
  return 0;
}

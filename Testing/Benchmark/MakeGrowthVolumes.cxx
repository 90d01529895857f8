// Writes the label maps of the growth benchmark (Utilities/growth-benchmark.sh) into a folder: shapes
// whose slabs are long and thin or crowded, each at four sizes doubling, 1 mm voxels:
//   speck-row-N.nrrd   N single voxels two apart in a row of one slice (N = 1000 .. 8000)
//   bar-N.nrrd         a bar one voxel thick and N long in one slice (N = 1000 .. 8000)
//   comb-N.nrrd        a spine with N teeth one voxel thick and 16 long, in one slice (N = 250 .. 2000)
//   rings-N.nrrd       N nested rings one voxel thick, a voxel apart, in one slice (N = 16 .. 128)
//   sphere-N.nrrd      a ball of radius N (N = 16 .. 128): a surface four times larger each step
// The surface of the first three grows with N, of the last two with N squared.
// Usage: MakeGrowthVolumes <output folder>
#include "MaskFileWriter.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>

namespace
{

using namespace slicemesh;

/** A mask of nx x ny x nz voxels of 1 mm whose voxel (i, j, k) is inside(i, j, k). */
MaskVolume::Pointer maskOf(int nx, int ny, int nz, const std::function<bool(int, int, int)>& inside)
{
  MaskVolume::Pointer mask = MaskVolume::New();
  MaskVolume::RegionType region;
  region.SetSize({ static_cast<itk::SizeValueType>(nx), static_cast<itk::SizeValueType>(ny),
                   static_cast<itk::SizeValueType>(nz) });
  mask->SetRegions(region);
  mask->Allocate();
  unsigned char* voxel = mask->GetBufferPointer();
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        *voxel++ = inside(i, j, k) ? 1 : 0;
  return mask;
}

/** A mask of nx x ny voxels in the middle one of three slices. */
MaskVolume::Pointer oneSlice(int nx, int ny, const std::function<bool(int, int)>& inside)
{
  return maskOf(nx, ny, 3, [&](int i, int j, int k) { return k == 1 && inside(i, j); });
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "Usage: " << argv[0] << " <output folder>\n";
    return 1;
  }
  const std::filesystem::path folder(argv[1]);
  std::filesystem::create_directories(folder);
  auto write = [&](const MaskVolume::Pointer& mask, const std::string& name, int n)
  { writeMaskFile(mask, (folder / (name + "-" + std::to_string(n) + ".nrrd")).string()); };
  constexpr int margin = 4;
  for (int n : { 1000, 2000, 4000, 8000 })
  {
    write(oneSlice(2 * n + 2 * margin, 3, [&](int i, int j) { return j == 1 && i >= margin && i < margin + 2 * n && (i - margin) % 2 == 0; }),
          "speck-row", n);
    write(oneSlice(n + 2 * margin, 3, [&](int i, int j) { return j == 1 && i >= margin && i < margin + n; }), "bar", n);
  }
  for (int n : { 250, 500, 1000, 2000 })
    write(oneSlice(2 * n + 2 * margin, 16 + 2 * margin,
                   [&](int i, int j)
                   {
                     const bool along = i >= margin && i < margin + 2 * n;
                     return along && (j == margin || (j > margin && j < margin + 16 && (i - margin) % 2 == 0));
                   }),
          "comb", n);
  for (int n : { 16, 32, 64, 128 })
  {
    const int side = 4 * n + 10;
    const double c = 0.5 * side;
    write(oneSlice(side, side,
                   [&](int i, int j)
                   {
                     const double r = std::hypot(i - c, j - c);
                     return r < 2.0 * n && static_cast<long>(std::floor(r)) % 2 == 0;
                   }),
          "rings", n);
    const int box = 2 * n + 6;
    const double middle = 0.5 * (box - 1);
    write(maskOf(box, box, box,
                 [&](int i, int j, int k)
                 { return (i - middle) * (i - middle) + (j - middle) * (j - middle) + (k - middle) * (k - middle) <= n * n; }),
          "sphere", n);
  }
  return 0;
}

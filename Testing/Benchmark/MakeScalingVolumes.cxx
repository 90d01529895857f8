// Writes the label maps of the scaling benchmark (Utilities/scaling-benchmark.sh) into a folder:
//   ellipsoid-large.nrrd     an ellipsoid of 220 x 190 x 264 mm at 0.5 x 0.5 x 1 mm (about 448 x 388 x 268)
//   ellipsoid-thick.nrrd     the same ellipsoid at 0.8 x 0.8 x 3 mm
//   labels-60.nrrd           60 labelled ellipsoids of varied size and tilt on 256^3 at 1 mm, some touching
//   ct-like.nrrd             a whole-body CT segmentation, 87 labels on 512 x 512 x 400 (CtLikeLabelMap.h)
//   sphere-128.nrrd, sphere-256.nrrd, sphere-512.nrrd
//                            one sphere of radius 62 mm at 1, 0.5 and 0.25 mm (128^3 .. 512^3 voxels)
// Usage: MakeScalingVolumes <output folder>
#include "CtLikeLabelMap.h"
#include "Ellipsoid.h"
#include "MaskFileWriter.h"
#include "PhantomGrid.h"
#include "Sphere.h"

#include <Eigen/Geometry>

#include <filesystem>
#include <iostream>
#include <random>

namespace
{

using namespace slicemesh;

/** A grid of `size` voxels of `spacing` mm centred on the origin. */
GridSpec centredGrid(std::array<std::size_t, 3> size, std::array<double, 3> spacing)
{
  GridSpec grid;
  grid.size = size;
  grid.spacing = spacing;
  for (int a = 0; a < 3; ++a)
    grid.origin[a] = -0.5 * static_cast<double>(size[a] - 1) * spacing[a];
  return grid;
}

/** 60 ellipsoids in a 4 x 4 x 4 arrangement (4 places left empty), jittered, radii 12-30 mm: close
 *  neighbours touch. Label n + 1 for the n-th ellipsoid; where two overlap the later one wins. */
MaskVolume::Pointer sixtyLabels()
{
  const GridSpec grid = centredGrid({ 256, 256, 256 }, { 1.0, 1.0, 1.0 });
  MaskVolume::Pointer labels = rasterizePhantom(Sphere(Vector3(1e6, 0, 0), 1.0), grid); // all 0
  std::mt19937 random(60);
  std::uniform_real_distribution<double> jitter(-8.0, 8.0), radius(12.0, 30.0), angle(0.0, 3.14159);
  int label = 0;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4 && label < 60; ++x)
      {
        const Vector3 centre(-96.0 + 64.0 * x + jitter(random), -96.0 + 64.0 * y + jitter(random),
                             -96.0 + 64.0 * z + jitter(random));
        const Matrix3 tilt = Eigen::AngleAxisd(angle(random), Vector3(jitter(random), jitter(random), 8.0).normalized())
                               .toRotationMatrix();
        const Ellipsoid blob(centre, Vector3(radius(random), radius(random), radius(random)), tilt);
        const MaskVolume::Pointer mask = rasterizePhantom(blob, grid);
        ++label;
        const unsigned char* in = mask->GetBufferPointer();
        unsigned char* out = labels->GetBufferPointer();
        for (std::size_t n = 0, count = mask->GetBufferedRegion().GetNumberOfPixels(); n < count; ++n)
          if (in[n])
            out[n] = static_cast<unsigned char>(label);
      }
  return labels;
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
  const Ellipsoid ellipsoid(Vector3(0, 0, 0), Vector3(110.0, 95.0, 132.0));
  writeMaskFile(rasterizePhantom(ellipsoid, gridAround(ellipsoid, { 0.5, 0.5, 1.0 }, 2)),
                (folder / "ellipsoid-large.nrrd").string());
  writeMaskFile(rasterizePhantom(ellipsoid, gridAround(ellipsoid, { 0.8, 0.8, 3.0 }, 2)),
                (folder / "ellipsoid-thick.nrrd").string());
  writeMaskFile(sixtyLabels(), (folder / "labels-60.nrrd").string());
  writeMaskFile(ctLikeLabelMap(), (folder / "ct-like.nrrd").string());
  const Sphere sphere(Vector3(0, 0, 0), 62.0);
  for (const auto& [name, voxels, spacing] : { std::tuple{ "sphere-128.nrrd", std::size_t(128), 1.0 },
                                               std::tuple{ "sphere-256.nrrd", std::size_t(256), 0.5 },
                                               std::tuple{ "sphere-512.nrrd", std::size_t(512), 0.25 } })
    writeMaskFile(rasterizePhantom(sphere, centredGrid({ voxels, voxels, voxels }, { spacing, spacing, spacing })),
                  (folder / name).string());
  return 0;
}

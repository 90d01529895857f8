// Writes the sample input of the README's main job: a label map of a kidney-like shape.
//   label 1: an elongated, tilted ellipsoid with an enclosed cavity (the "renal sinus"),
//   label 2: a ball on its lateral side (a "lesion") that cuts into label 1: the two touch.
// The grid is anisotropic (0.8 x 0.8 x 2 mm) and slightly oblique, as scanner data usually is.
//
// Usage: MakeSampleVolume <output.nii.gz>
#include "Ellipsoid.h"
#include "MaskFileWriter.h"
#include "PhantomCombinators.h"
#include "PhantomGrid.h"
#include "Sphere.h"

#include <Eigen/Geometry>

#include <iostream>

int main(int argc, char* argv[])
{
  using namespace slicemesh;
  if (argc != 2)
  {
    std::cerr << "Usage: " << argv[0] << " <output.nii.gz>\n";
    return 1;
  }

  const Vector3 center(10.0, -20.0, 30.0);
  const Matrix3 tilt = Eigen::AngleAxisd(0.35, Vector3::UnitY()).toRotationMatrix();
  auto kidney = std::make_shared<NestedSubtraction>(
    std::make_shared<Ellipsoid>(center, Vector3(24.0, 14.0, 48.0), tilt),
    std::make_shared<Ellipsoid>(center + Vector3(3.0, 0.0, 0.0), Vector3(9.0, 5.0, 24.0), tilt));
  auto lesion = std::make_shared<Sphere>(center + tilt * Vector3(-20.0, 0.0, 12.0), 11.0);
  const DisjointUnion both(kidney, lesion); // only for the grid: its bounds cover both labels

  const Matrix3 oblique = (Eigen::AngleAxisd(0.14, Vector3::UnitZ()) * Eigen::AngleAxisd(0.09, Vector3::UnitX())).toRotationMatrix();
  const GridSpec grid = gridAround(both, { 0.8, 0.8, 2.0 }, 2, oblique);

  // The mask of the union fixes the geometry; then label each inside voxel.
  MaskVolume::Pointer labels = rasterizePhantom(both, grid);
  unsigned char* voxel = labels->GetBufferPointer();
  for (std::size_t k = 0; k < grid.size[2]; ++k)
    for (std::size_t j = 0; j < grid.size[1]; ++j)
      for (std::size_t i = 0; i < grid.size[0]; ++i, ++voxel)
        if (*voxel)
          *voxel = lesion->signedDistance(grid.physicalPoint(i, j, k)) <= 0.0 ? 2 : 1;

  try
  {
    writeMaskFile(labels, argv[1]);
  }
  catch (const Error& error)
  {
    std::cerr << error.what() << "\n";
    return 1;
  }
  std::cout << argv[1] << ": " << grid.size[0] << " x " << grid.size[1] << " x " << grid.size[2] << " voxels\n";
  return 0;
}

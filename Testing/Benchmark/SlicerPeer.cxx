// 3D Slicer's label map -> closed surface conversion as a command, for the scaling benchmark: reads a
// label map, converts every non-zero label one at a time on its own extent (as Slicer converts each
// segment), writes the merged surface. Prints "triangles <n> meshing <s>", meshing being the time
// between the read volume and the merged surface (reading and writing excluded). With a third
// argument, writes there a line "label voxels voxel-volume surface-volume" per label: its voxel
// count, their volume and the volume its surface encloses (mm^3), for Utilities/label-volumes.sh.
// Usage: SlicerPeer <label map> <output.vtp> [volumes.tsv]
#include "ContourExtraction.h"
#include "LabelIndex.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "MeshWriter.h"
#include "SlicerPipeline.h"
#include "VolumeReader.h"

#include <vnl/vnl_det.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <iostream>

int main(int argc, char* argv[])
{
  using namespace slicemesh;
  if (argc != 3 && argc != 4)
  {
    std::cerr << "Usage: " << argv[0] << " <label map> <output.vtp> [volumes.tsv]\n";
    return 2;
  }
  try
  {
    const ScalarVolume::Pointer volume = readVolume(argv[1]);
    const auto began = std::chrono::steady_clock::now();
    std::vector<TriangleMesh> surfaces;
    const std::vector<LabelExtent> labels = indexLabels(volume);
    for (const LabelExtent& extent : labels)
    {
      const MaskVolume::Pointer mask = cropLabelMask(volume, extent);
      surfaces.push_back(mapToPhysicalSpace(slicerSurface(mask), sliceFrameOf(mask), CoordinateSystem::LPS));
    }
    std::vector<const TriangleMesh*> parts;
    for (const TriangleMesh& surface : surfaces)
      parts.push_back(&surface);
    const TriangleMesh merged = joinMeshes(parts);
    const double meshing = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    writeMesh(merged, CoordinateSystem::LPS, argv[2]);
    if (argc == 4)
    {
      const auto& spacing = volume->GetSpacing();
      const double voxel = spacing[0] * spacing[1] * spacing[2] * std::abs(vnl_det(volume->GetDirection().GetVnlMatrix()));
      std::ofstream volumes(argv[3]);
      volumes.precision(10);
      for (std::size_t n = 0; n < labels.size(); ++n)
        volumes << labels[n].label << " " << labels[n].voxels << " " << voxel * double(labels[n].voxels) << " "
                << std::abs(signedVolume(surfaces[n])) << "\n";
      if (!volumes)
        throw std::runtime_error(std::string("cannot write '") + argv[3] + "'");
    }
    std::printf("triangles %zu meshing %.3f\n", merged.triangles.size(), meshing);
  }
  catch (const std::exception& e)
  {
    std::cerr << "SlicerPeer: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

// 3D Slicer's label map -> closed surface conversion as a command, for the scaling benchmark: reads a
// label map, converts every non-zero label one at a time on its own extent (as Slicer converts each
// segment), writes the merged surface. Prints "triangles <n> meshing <s>", meshing being the time
// between the read volume and the merged surface (reading and writing excluded).
// Usage: SlicerPeer <label map> <output.vtp>
#include "ContourExtraction.h"
#include "LabelIndex.h"
#include "Measures/MeshComponents.h"
#include "MeshWriter.h"
#include "SlicerPipeline.h"
#include "VolumeReader.h"

#include <chrono>
#include <cstdio>
#include <iostream>

int main(int argc, char* argv[])
{
  using namespace slicemesh;
  if (argc != 3)
  {
    std::cerr << "Usage: " << argv[0] << " <label map> <output.vtp>\n";
    return 2;
  }
  try
  {
    const ScalarVolume::Pointer volume = readVolume(argv[1]);
    const auto began = std::chrono::steady_clock::now();
    std::vector<TriangleMesh> surfaces;
    for (const LabelExtent& extent : indexLabels(volume))
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
    std::printf("triangles %zu meshing %.3f\n", merged.triangles.size(), meshing);
  }
  catch (const std::exception& e)
  {
    std::cerr << "SlicerPeer: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

// 3D Slicer's label map -> closed surface conversion as a command, for the scaling benchmark: reads a
// label map, converts every non-zero label one at a time on its own extent (as Slicer converts each
// segment), writes the merged surface. Prints "triangles <n> meshing <s>", meshing being the time
// between the read volume and the merged surface (reading and writing excluded).
// Usage: SlicerPeer <label map> <output.vtp>
#include "ContourExtraction.h"
#include "LabelIndex.h"
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
    TriangleMesh merged;
    for (const LabelExtent& extent : indexLabels(volume))
    {
      const MaskVolume::Pointer mask = cropLabelMask(volume, extent);
      const TriangleMesh physical = mapToPhysicalSpace(slicerSurface(mask), sliceFrameOf(mask), CoordinateSystem::LPS);
      const auto offset = static_cast<std::int32_t>(merged.points.size());
      merged.points.insert(merged.points.end(), physical.points.begin(), physical.points.end());
      for (const Triangle& t : physical.triangles)
        merged.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    }
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

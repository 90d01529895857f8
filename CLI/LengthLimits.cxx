#include "LengthLimits.h"

#include "SliceMeshPipeline.h"

#include <sstream>

namespace slicemesh::cli
{

void requireResolvableLengths(const MeshingOptions& options, double smallestVoxelSide)
{
  const double smallest = smallestLengthPerVoxelSide * smallestVoxelSide;
  struct Length
  {
    const char* flag;
    const char* label;
    double value;
  };
  for (const Length& length : { Length{ "--targetEdgeLength", "Target edge length", options.finishing.remeshing.targetEdgeLength },
                                Length{ "--maxEdgeLength", "Maximum edge length", options.reconstruction.maxEdgeLength },
                                Length{ "--wallRowHeight", "Wall row height", options.reconstruction.wallRowHeight },
                                Length{ "--contourPointSpacing", "Point spacing", options.contours.pointSpacing } })
    if (length.value > 0.0 && length.value < smallest)
    {
      std::ostringstream message;
      message << length.flag << " (" << length.label << "): " << length.value
              << " mm is under a twentieth of the smallest voxel side (" << smallestVoxelSide
              << " mm): use at least " << smallest << " mm, or 0 for automatic";
      throw PipelineFailure(BadArguments, message.str());
    }
}

} // namespace slicemesh::cli

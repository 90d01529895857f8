#include "Finishing/PieceRejection.h"

namespace slicemesh
{

std::string rejection(const MeshValidation& candidate, const MeshValidation& tiled)
{
  if (!(candidate.closed() && candidate.manifold() && candidate.inconsistentEdges == 0 &&
        candidate.degenerateTriangles == 0 && candidate.selfIntersectionChecked && candidate.selfIntersections == 0))
    return candidate.summary();
  if (candidate.components != tiled.components || candidate.eulerCharacteristic != tiled.eulerCharacteristic)
  {
    return "its topology changed (" + std::to_string(candidate.components) + " components and Euler characteristic " +
           std::to_string(candidate.eulerCharacteristic) + " instead of " + std::to_string(tiled.components) +
           " and " + std::to_string(tiled.eulerCharacteristic) + ")";
  }
  if (!(candidate.volume * tiled.volume > 0.0))
    return "it turned inside out";
  return {};
}

} // namespace slicemesh

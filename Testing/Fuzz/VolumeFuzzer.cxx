// libFuzzer target on the volume path: a tiny random mask decoded from the bytes goes through
// extractContours -> reconstructSurface -> mapToPhysicalSpace -> validateMesh. A slicemesh::Error
// is a fine answer; a crash, a sanitizer report, another exception or a hang is a bug.
// With SLICEMESH_FUZZ_STRICT=1 a mesh that is not valid aborts too (the property test's rule).
//
// Decoding: three bytes give the size (1..8 per axis), one the spacing and direction, the rest
// are the voxels, one bit each (missing bytes are zero).
#include "ContourExtraction.h"
#include "Measures/MeshValidation.h"
#include "MeshWriter.h"
#include "Tiling/SurfaceReconstruction.h"

#include <cstdint>
#include <cstdlib>
#include <cstddef>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace slicemesh;
  if (size < 4)
    return 0;
  MaskVolume::SizeType extent;
  for (unsigned int a = 0; a < 3; ++a)
    extent[a] = 1 + data[a] % 8;
  const std::uint8_t style = data[3];
  const double spacings[4][3] = { { 1, 1, 1 }, { 0.7, 0.7, 3 }, { 0.5, 1.25, 2 }, { 2.5, 2.5, 2.5 } };
  MaskVolume::SpacingType spacing;
  for (unsigned int a = 0; a < 3; ++a)
    spacing[a] = spacings[style % 4][a];
  MaskVolume::DirectionType direction;
  direction.SetIdentity();
  if (style & 4)
    direction[0][0] = -1.0; // mirrored
  if (style & 8)
  { // oblique: 30 degrees about z
    direction[0][0] = 0.8660254037844386, direction[0][1] = -0.5;
    direction[1][0] = 0.5, direction[1][1] = 0.8660254037844386;
  }
  auto mask = MaskVolume::New();
  mask->SetRegions(extent);
  mask->SetSpacing(spacing);
  mask->SetDirection(direction);
  mask->Allocate(true);
  unsigned char* voxel = mask->GetBufferPointer();
  const std::size_t count = extent[0] * extent[1] * extent[2];
  for (std::size_t v = 0; v < count; ++v)
  {
    const std::size_t byte = 4 + v / 8;
    voxel[v] = byte < size ? (data[byte] >> (v % 8)) & 1 : 0;
  }
  try
  {
    const ContourStack stack = extractContours(mask);
    const TriangleMesh mesh = reconstructSurface(stack);
    const MeshValidation validation =
      validateMesh(mapToPhysicalSpace(mesh, sliceFrameOf(mask), CoordinateSystem::LPS));
    static const bool strict = std::getenv("SLICEMESH_FUZZ_STRICT") != nullptr;
    if (strict && !validation.valid())
      std::abort();
  }
  catch (const Error&)
  {
  }
  return 0;
}

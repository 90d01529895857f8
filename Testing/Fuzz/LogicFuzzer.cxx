// libFuzzer target on Logic's entry point: a contour stack decoded from the bytes goes through
// reconstructSurface and, when a mesh comes out, validateMesh. A slicemesh::Error is a fine answer
// to bad input; a crash, a sanitizer report, another exception or a hang is a bug.
// With SLICEMESH_FUZZ_STRICT=1 an accepted stack whose mesh is not valid aborts too.
//
// Decoding (every byte string is a stack): byte 0 picks the slice count (1..6) and spacing; per
// slice a byte for its contour count (0..3); per contour a byte for its point count (3..14), then
// two bytes per point on a 0.25 mm grid of 16 x 16 mm, so coincident and collinear points,
// touching and crossing contours are common.
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <cstdint>
#include <cstdlib>
#include <cstddef>

namespace
{

struct Bytes
{
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;
  std::uint8_t next() { return at < size ? data[at++] : 0; }
  bool done() const { return at >= size; }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace slicemesh;
  Bytes bytes{ data, size };
  const std::uint8_t head = bytes.next();
  ContourStack stack;
  const int slices = 1 + head % 6;
  const double spacings[4] = { 1.0, 0.5, 2.5, 0.0 };
  stack.sliceSpacing = spacings[(head / 6) % 4];
  if (slices == 1 && stack.sliceSpacing == 0.0)
    stack.sliceSpacing = 1.0;
  const double dz = stack.sliceSpacing > 0.0 ? stack.sliceSpacing : 1.5;
  for (int k = 0; k < slices && !bytes.done(); ++k)
  {
    Slice slice;
    slice.z = k * dz;
    const int contours = bytes.next() % 4;
    for (int c = 0; c < contours && !bytes.done(); ++c)
    {
      const int points = 3 + bytes.next() % 12;
      Polygon2 polygon;
      for (int p = 0; p < points; ++p)
        polygon.push_back({ 0.25 * (bytes.next() % 64), 0.25 * (bytes.next() % 64) });
      slice.contours.push_back(polygon);
    }
    stack.slices.push_back(slice);
  }
  try
  {
    ReconstructionOptions options;
    const TriangleMesh mesh = reconstructSurface(stack, options);
    const MeshValidation validation = validateMesh(mesh);
    static const bool strict = std::getenv("SLICEMESH_FUZZ_STRICT") != nullptr;
    if (strict && !validation.valid())
      std::abort();
  }
  catch (const Error&)
  {
  }
  return 0;
}

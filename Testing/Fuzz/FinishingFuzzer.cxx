// libFuzzer target on the finishing stage: a small voxel mask decoded from the bytes is traced
// (marching squares at the 0.5 level, as the CLI traces label maps), tiled, and when the tiling is
// valid, remeshed whole (every piece, specks included, which the finishing itself leaves as tiled)
// and finished as the CLI finishes it. A slicemesh::Error is a fine answer; a crash (CGAL's remesher
// included), a sanitizer report or a hang is a bug. The finished mesh of a valid tiling must be
// valid: the stage falls back piece by piece rather than hand back a broken surface.
//
// Decoding: byte 0 picks the grid (nx, ny in 2..9, nz in 1..6 from its bits) and byte 1 the spacing
// and cap placement; then one bit per voxel, row by row, slice by slice (missing bytes are 0).
#include "Contours/MarchingSquares.h"
#include "Measures/MeshValidation.h"
#include "Finishing/SurfaceFinishing.h"
#include "Tiling/SurfaceReconstruction.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace
{

struct Bits
{
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;
  std::uint8_t byte() { return at / 8 < size ? data[at / 8] : 0; }
  std::uint8_t next()
  {
    const std::uint8_t b = byte();
    at += 8;
    return b;
  }
  bool bit()
  {
    const bool b = (at / 8 < size) && ((data[at / 8] >> (at % 8)) & 1);
    ++at;
    return b;
  }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace slicemesh;
  Bits bits{ data, size };
  const std::uint8_t grid = bits.next(), style = bits.next();
  const std::size_t nx = 2 + grid % 8, ny = 2 + (grid / 8) % 8, nz = 1 + (grid / 64) % 6;
  const std::array<std::array<double, 3>, 4> spacings{ { { 1.0, 1.0, 1.0 }, { 0.7, 0.7, 3.0 }, { 0.5, 0.5, 1.3 },
                                                         { 1.2, 1.2, 2.0 } } };
  const std::array<double, 3> spacing = spacings[style % 4];

  ContourStack stack;
  stack.sliceSpacing = spacing[2];
  for (std::size_t k = 0; k < nz; ++k)
  {
    // Nodes at the voxel centres, one node of background around: the 0.5 level of the mask.
    ScalarGrid2 slice;
    slice.cell = 1.0;
    slice.nx = nx + 2;
    slice.ny = ny + 2;
    slice.values.assign(slice.nx * slice.ny, 0.5);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        if (bits.bit())
          slice.values[(j + 1) * slice.nx + i + 1] = -0.5;
    Slice traced;
    traced.z = static_cast<double>(k) * spacing[2];
    for (Polygon2 contour : zeroContours(slice))
    {
      for (Point2& p : contour)
        p = { p.x * spacing[0], p.y * spacing[1] };
      traced.contours.push_back(contour);
    }
    stack.slices.push_back(traced);
  }
  try
  {
    ReconstructionOptions options;
    options.capPlacement = (style / 4) % 2 ? CapPlacement::AtSlice : CapPlacement::HalfSliceBeyond;
    const TriangleMesh tiling = reconstructSurface(stack, options);
    if (tiling.triangles.empty())
      return 0;
    const MeshValidation validation = validateMesh(tiling);
    if (!validation.valid())
      return 0; // the Logic fuzzer's and the property test's concern
    SurfaceFinishingOptions finishing = finishingOptionsFor(spacing);
    remeshSurface(tiling, finishing.remeshing);
    const FinishedSurface finished = finishSurface(tiling, validation, finishing);
    if (!validateMesh(finished.mesh).valid())
      std::abort();
  }
  catch (const Error&)
  {
  }
  return 0;
}

#include "ReliabilitySupport.h"

#include "ContourExtraction.h"
#include "MeshWriter.h"

#include <cmath>
#include <random>
#include <sstream>

namespace slicemesh::testing
{

MaskVolume::Pointer makeMask(std::array<std::size_t, 3> size, std::array<double, 3> spacing,
                             const std::array<std::array<double, 3>, 3>& direction)
{
  auto mask = MaskVolume::New();
  MaskVolume::SizeType itkSize;
  MaskVolume::SpacingType itkSpacing;
  MaskVolume::DirectionType itkDirection;
  for (unsigned int a = 0; a < 3; ++a)
  {
    itkSize[a] = size[a];
    itkSpacing[a] = spacing[a];
    for (unsigned int b = 0; b < 3; ++b)
      itkDirection[a][b] = direction[a][b];
  }
  mask->SetRegions(itkSize);
  mask->SetSpacing(itkSpacing);
  mask->SetDirection(itkDirection);
  mask->Allocate(true);
  return mask;
}

MaskVolume::Pointer makeMask(std::array<std::size_t, 3> size, std::array<double, 3> spacing,
                             const std::function<bool(long, long, long)>& inside)
{
  MaskVolume::Pointer mask = makeMask(size, spacing);
  for (long k = 0; k < static_cast<long>(size[2]); ++k)
    for (long j = 0; j < static_cast<long>(size[1]); ++j)
      for (long i = 0; i < static_cast<long>(size[0]); ++i)
        if (inside(i, j, k))
          mask->SetPixel({ { i, j, k } }, 1);
  return mask;
}

std::string MaskMeshResult::problem() const
{
  std::ostringstream text;
  if (!error.empty())
    text << "threw: " << error;
  else if (!validation.valid())
    text << "invalid mesh: " << validation.summary() << " (boundary " << validation.boundaryEdges
         << ", non-manifold edges " << validation.nonManifoldEdges << ", non-manifold vertices "
         << validation.nonManifoldVertices << ", inconsistent " << validation.inconsistentEdges << ", degenerate "
         << validation.degenerateTriangles << ", self-intersections " << validation.selfIntersections
         << (validation.selfIntersectionChecked ? "" : " (not checked)") << ")";
  else if (!volumeWithinTolerance())
    text << "volume " << validation.volume << " mm^3, voxels " << voxelVolume << " mm^3, tolerance "
         << volumeTolerance() << " mm^3";
  return text.str();
}

MaskMeshResult checkedMesh(const MaskVolume* mask, const MeshingOptions& options)
{
  MaskMeshResult result;
  result.capsAtSlice = options.reconstruction.capPlacement == CapPlacement::AtSlice;
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  const auto spacing = mask->GetSpacing();
  result.maxSpacing = std::max({ spacing[0], spacing[1], spacing[2] });
  const double faceArea[3] = { spacing[1] * spacing[2], spacing[0] * spacing[2], spacing[0] * spacing[1] };
  std::size_t voxels = 0;
  auto at = [&](long i, long j, long k) -> bool
  {
    if (i < 0 || j < 0 || k < 0 || i >= static_cast<long>(size[0]) || j >= static_cast<long>(size[1]) ||
        k >= static_cast<long>(size[2]))
      return false;
    return mask->GetPixel({ { i, j, k } }) != 0;
  };
  for (long k = 0; k < static_cast<long>(size[2]); ++k)
    for (long j = 0; j < static_cast<long>(size[1]); ++j)
      for (long i = 0; i < static_cast<long>(size[0]); ++i)
        if (at(i, j, k))
        {
          ++voxels;
          const long step[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
          for (int a = 0; a < 3; ++a)
          {
            if (!at(i + step[a][0], j + step[a][1], k + step[a][2]))
              result.voxelFaceArea += faceArea[a];
            if (!at(i - step[a][0], j - step[a][1], k - step[a][2]))
              result.voxelFaceArea += faceArea[a];
          }
        }
  result.voxelVolume = static_cast<double>(voxels) * spacing[0] * spacing[1] * spacing[2];
  try
  {
    result.meshing = startMaskMeshing(mask, options);
    runMeshingStage(MeshingStage::Preparation, result.meshing);
    for (const Slice& slice : result.meshing.stack.slices)
      result.contours += slice.contours.size();
    for (MeshingStage stage : { MeshingStage::Correspondence, MeshingStage::Tiling, MeshingStage::Validation,
                                MeshingStage::Finishing })
      runMeshingStage(stage, result.meshing);
    result.mesh = mapToPhysicalSpace(result.meshing.surface.mesh, sliceFrameOf(mask), CoordinateSystem::LPS);
    result.validation = validateMesh(result.mesh);
  }
  catch (const std::exception& e)
  {
    result.error = e.what();
  }
  return result;
}

MaskMeshResult checkedMesh(const MaskVolume* mask, const ReconstructionOptions& options)
{
  MeshingOptions tiling;
  tiling.reconstruction = options;
  tiling.finishing.finish = SurfaceFinish::Tiled;
  return checkedMesh(mask, tiling);
}

namespace
{

using Direction = std::array<std::array<double, 3>, 3>;

Direction rotationAbout(std::array<double, 3> axis, double angle)
{
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (double& a : axis)
    a /= n;
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return { { { t * x * x + c, t * x * y - s * z, t * x * z + s * y },
             { t * x * y + s * z, t * y * y + c, t * y * z - s * x },
             { t * x * z - s * y, t * y * z + s * x, t * z * z + c } } };
}

const char* kindName(RandomMaskKind kind)
{
  switch (kind)
  {
    case RandomMaskKind::Blobs: return "blobs";
    case RandomMaskKind::Noise: return "noise";
    case RandomMaskKind::BlobsAndNoise: return "blobs+noise";
    case RandomMaskKind::Touching: return "touching";
    case RandomMaskKind::Thin: return "thin";
    case RandomMaskKind::ThresholdedMri: return "thresholded MRI";
    default: return "any";
  }
}

} // namespace

RandomMask randomMask(std::uint64_t seed, RandomMaskKind kind)
{
  std::mt19937_64 random(seed * 0x9E3779B97F4A7C15ull + 12345u);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
  auto integer = [&](long a, long b) { return std::uniform_int_distribution<long>(a, b)(random); };
  if (kind == RandomMaskKind::Any)
    kind = static_cast<RandomMaskKind>(integer(0, 4));

  std::array<std::size_t, 3> size;
  for (auto& s : size)
    s = static_cast<std::size_t>(kind == RandomMaskKind::ThresholdedMri ? integer(12, 28)
                                                                         : integer(kind == RandomMaskKind::Thin ? 1 : 2, 16));
  if (integer(0, 9) == 0)
    size[2] = 1; // a single slice
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  switch (integer(0, 3))
  {
    case 0: break;                                                     // isotropic 1 mm
    case 1: spacing = { 0.7, 0.7, 3.0 }; break;                        // thick slices
    case 2: spacing = { uniform(0.3, 2.0), uniform(0.3, 2.0), uniform(0.3, 4.0) }; break; // anisotropic
    default: { const double s = uniform(0.2, 2.5); spacing = { s, s, s }; }
  }
  Direction direction{ { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
  std::string directionName = "identity";
  switch (integer(0, 3))
  {
    case 0: break;
    case 1:
      direction = rotationAbout({ uniform(-1, 1), uniform(-1, 1), uniform(0.1, 1) }, uniform(0.1, 3.0));
      directionName = "oblique";
      break;
    case 2:
      direction = { { { -1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
      directionName = "mirrored";
      break;
    default:
      direction = { { { 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 } } }; // sagittal-like axes
      directionName = "permuted";
  }
  MaskVolume::Pointer mask = makeMask(size, spacing, direction);
  const long nx = static_cast<long>(size[0]), ny = static_cast<long>(size[1]), nz = static_cast<long>(size[2]);
  auto set = [&](long i, long j, long k)
  {
    if (i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz)
      mask->SetPixel({ { i, j, k } }, 1);
  };

  auto addBlobs = [&]
  {
    const long count = integer(1, 4);
    for (long b = 0; b < count; ++b)
    {
      // Centre anywhere, border included, radii in voxels: cut by the border now and then.
      const double c[3] = { uniform(-1, nx), uniform(-1, ny), uniform(-1, nz) };
      const double r[3] = { uniform(0.4, 0.6 * nx + 1), uniform(0.4, 0.6 * ny + 1), uniform(0.4, 0.6 * nz + 1) };
      for (long k = 0; k < nz; ++k)
        for (long j = 0; j < ny; ++j)
          for (long i = 0; i < nx; ++i)
          {
            const double u = (i - c[0]) / r[0], v = (j - c[1]) / r[1], w = (k - c[2]) / r[2];
            if (u * u + v * v + w * w <= 1.0)
              set(i, j, k);
          }
    }
  };
  auto addNoise = [&](double density)
  {
    for (long k = 0; k < nz; ++k)
      for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i)
          if (uniform(0, 1) < density)
            set(i, j, k);
  };

  switch (kind)
  {
    case RandomMaskKind::Blobs:
      addBlobs();
      break;
    case RandomMaskKind::Noise:
      addNoise(uniform(0.02, 0.6));
      break;
    case RandomMaskKind::BlobsAndNoise:
      addBlobs();
      addNoise(uniform(0.01, 0.15));
      break;
    case RandomMaskKind::Touching:
    {
      // Diagonal runs in and across slices, checkerboard patches, corner-only touches.
      const long pieces = integer(1, 6);
      for (long p = 0; p < pieces; ++p)
      {
        long i = integer(0, nx - 1), j = integer(0, ny - 1), k = integer(0, nz - 1);
        switch (integer(0, 3))
        {
          case 0: // in-plane diagonal run
          {
            const long di = integer(0, 1) ? 1 : -1, dj = integer(0, 1) ? 1 : -1, n = integer(2, 8);
            for (long s = 0; s < n; ++s)
              set(i + s * di, j + s * dj, k);
            break;
          }
          case 1: // across slices: (i, j, k), (i + 1, j, k + 1), ... or a corner run (i+1, j+1, k+1)
          {
            const long dj = integer(0, 1), n = integer(2, 8);
            for (long s = 0; s < n; ++s)
              set(i + s, j + s * dj, k + s);
            break;
          }
          case 2: // checkerboard patch
          {
            const long w = integer(2, 6), h = integer(2, 6), d = integer(1, 4), parity = integer(0, 1);
            for (long c = 0; c < d; ++c)
              for (long b = 0; b < h; ++b)
                for (long a = 0; a < w; ++a)
                  if ((a + b + c + parity) % 2 == 0)
                    set(i + a, j + b, k + c);
            break;
          }
          default: // two boxes meeting at an edge or a corner
          {
            const long w = integer(1, 3);
            for (long c = 0; c < w; ++c)
              for (long b = 0; b < w; ++b)
                for (long a = 0; a < w; ++a)
                {
                  set(i + a, j + b, k + c);
                  set(i + w + a, j + w + b, k + (integer(0, 1) ? w : 0) + c);
                }
          }
        }
      }
      break;
    }
    case RandomMaskKind::ThresholdedMri:
    {
      // Six plane waves of 4 to 20 voxels' wavelength, summed and thresholded: folded sheets and
      // tubes that touch, branch and enclose holes, like a threshold through grey and white matter.
      std::array<std::array<double, 4>, 6> waves;
      for (auto& w : waves)
      {
        const double length = uniform(4.0, 20.0), theta = uniform(0.0, M_PI), phi = uniform(0.0, 2.0 * M_PI);
        const double k = 2.0 * M_PI / length;
        w = { k * std::sin(theta) * std::cos(phi), k * std::sin(theta) * std::sin(phi), k * std::cos(theta),
              uniform(0.0, 2.0 * M_PI) };
      }
      const double level = uniform(-1.5, 2.0);
      // The volume is cut off flat somewhere, as a field of view or a slab of slices is.
      const long firstSlice = integer(0, nz / 3), lastSlice = integer(2 * nz / 3, nz - 1);
      for (long k = firstSlice; k <= lastSlice; ++k)
        for (long j = 0; j < ny; ++j)
          for (long i = 0; i < nx; ++i)
          {
            double f = 0.0;
            for (const auto& w : waves)
              f += std::cos(w[0] * i + w[1] * j + w[2] * k + w[3]);
            if (f > level)
              set(i, j, k);
          }
      if (integer(0, 2) == 0)
        addNoise(uniform(0.002, 0.02));
      break;
    }
    case RandomMaskKind::Thin:
    default:
    {
      const long pieces = integer(1, 4);
      for (long p = 0; p < pieces; ++p)
      {
        const long k = integer(0, nz - 1);
        if (integer(0, 1))
        { // a one-slice sheet (a disk or a rectangle)
          const double ci = uniform(0, nx), cj = uniform(0, ny), r = uniform(0.5, 6);
          for (long j = 0; j < ny; ++j)
            for (long i = 0; i < nx; ++i)
              if ((i - ci) * (i - ci) + (j - cj) * (j - cj) <= r * r)
                set(i, j, k);
        }
        else
        { // a one-voxel rod along z, or a single voxel
          const long i = integer(0, nx - 1), j = integer(0, ny - 1), n = integer(1, nz);
          for (long s = 0; s < n; ++s)
            set(i, j, k + s);
        }
      }
    }
  }

  ReconstructionOptions options;
  if (kind == RandomMaskKind::ThresholdedMri && integer(0, 1))
    options.capPlacement = CapPlacement::AtSlice;
  std::ostringstream description;
  description << "seed " << seed << ", " << kindName(kind) << ", size " << nx << " x " << ny << " x " << nz
              << ", spacing " << spacing[0] << " x " << spacing[1] << " x " << spacing[2] << ", " << directionName
              << " direction" << (options.capPlacement == CapPlacement::AtSlice ? ", caps at the slice" : "");
  return { mask, description.str(), options };
}

std::string maskAsCode(const MaskVolume* mask)
{
  const auto size = mask->GetLargestPossibleRegion().GetSize();
  const auto spacing = mask->GetSpacing();
  std::ostringstream code;
  code.precision(17);
  code << "MaskVolume::Pointer mask = makeMask({ " << size[0] << ", " << size[1] << ", " << size[2] << " }, { "
       << spacing[0] << ", " << spacing[1] << ", " << spacing[2] << " });\nfor (const auto& v : std::vector<std::array<long, 3>>{";
  std::size_t n = 0;
  for (long k = 0; k < static_cast<long>(size[2]); ++k)
    for (long j = 0; j < static_cast<long>(size[1]); ++j)
      for (long i = 0; i < static_cast<long>(size[0]); ++i)
        if (mask->GetPixel({ { i, j, k } }))
          code << (n++ % 8 == 0 ? "\n  " : " ") << "{ " << i << ", " << j << ", " << k << " },";
  code << " })\n  mask->SetPixel({ { v[0], v[1], v[2] } }, 1);";
  return code.str();
}

} // namespace slicemesh::testing

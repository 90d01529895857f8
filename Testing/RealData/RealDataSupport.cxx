#include "RealDataSupport.h"

#include "MaskMeshing.h"

#include "ComponentLabeling.h"
#include "ContourExtraction.h"
#include "Core/DisjointSets.h"

#include "itkImageRegionConstIteratorWithIndex.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace slicemesh::testing
{

std::string externalData(const std::string& name)
{
  return std::string(SLICEMESH_EXTERNAL_DATA_DIR) + "/" + name;
}

std::string outputPath(const std::string& name)
{
  std::filesystem::create_directories(SLICEMESH_TEST_OUTPUT_DIR);
  return std::string(SLICEMESH_TEST_OUTPUT_DIR) + "/" + name;
}

void Box::add(const std::array<double, 3>& p)
{
  for (int a = 0; a < 3; ++a)
  {
    lower[a] = std::min(lower[a], p[a]);
    upper[a] = std::max(upper[a], p[a]);
  }
}

bool Box::contains(const Box& inner, double tolerance) const
{
  for (int a = 0; a < 3; ++a)
    if (inner.lower[a] < lower[a] - tolerance || inner.upper[a] > upper[a] + tolerance)
      return false;
  return true;
}

MaskMesh tiledMask(const MaskVolume* mask, const ReconstructionOptions& options)
{
  MaskMesh result;
  MeshingOptions tiling; // the one meshing path, the tiling alone
  tiling.reconstruction = options;
  tiling.finishing.finish = SurfaceFinish::Tiled;
  const MeshedMask meshed = slicemesh::meshMask(mask, tiling);
  result.validation = meshed.meshing.tilingValidation;
  result.physical = meshed.physical;
  for (const Point3& p : result.physical.points)
    result.meshBox.add({ p.x, p.y, p.z });

  const auto region = mask->GetBufferedRegion();
  const auto spacing = mask->GetSpacing();
  const auto direction = mask->GetDirection();
  result.voxelVolume = 0.0;
  const unsigned char* voxel = mask->GetBufferPointer();
  for (itk::ImageRegionConstIteratorWithIndex<MaskVolume> it(mask, region); !it.IsAtEnd(); ++it)
  {
    if (!it.Get())
      continue;
    itk::Point<double, 3> centre;
    mask->TransformIndexToPhysicalPoint(it.GetIndex(), centre);
    result.centreBox.add({ centre[0], centre[1], centre[2] });
    for (int corner = 0; corner < 8; ++corner)
    {
      std::array<double, 3> p{ centre[0], centre[1], centre[2] };
      for (int axis = 0; axis < 3; ++axis)
      {
        const double half = ((corner >> axis) & 1 ? 0.5 : -0.5) * spacing[axis];
        for (int row = 0; row < 3; ++row)
          p[row] += direction[row][axis] * half;
      }
      result.cubeBox.add(p);
    }
    result.voxelVolume += spacing[0] * spacing[1] * spacing[2];
  }
  (void)voxel;
  return result;
}

namespace
{

/** For the slab between slices k and k + 1 (k = 0 .. nz - 2): a representative per 2D region id
 *  such that two regions of slices k and k + 1 have the same one exactly when they are tiled
 *  together (a chain of regions overlapping from one slice to the other). */
class SlabGroups
{
public:
  SlabGroups(const ComponentLabels& regions, long nx, long ny, long nz)
    : m_Regions(regions)
    , m_Slice(static_cast<std::size_t>(nx * ny))
  {
    for (long k = 0; k + 1 < nz; ++k)
    {
      DisjointSets groups(static_cast<std::size_t>(regions.count) + 1);
      const std::size_t below = static_cast<std::size_t>(k) * m_Slice, above = below + m_Slice;
      for (std::size_t p = 0; p < m_Slice; ++p)
        if (regions.labels[below + p] > 0 && regions.labels[above + p] > 0)
          groups.unite(static_cast<std::size_t>(regions.labels[below + p]),
                       static_cast<std::size_t>(regions.labels[above + p]));
      m_Groups.push_back(std::move(groups));
    }
  }
  /** Whether voxels n (slice k) and m (slice k + 1), both foreground, are tiled together. */
  bool together(long k, long n, long m)
  {
    DisjointSets& groups = m_Groups[static_cast<std::size_t>(k)];
    return groups.find(static_cast<std::size_t>(m_Regions.labels[static_cast<std::size_t>(n)])) ==
           groups.find(static_cast<std::size_t>(m_Regions.labels[static_cast<std::size_t>(m)]));
  }

private:
  const ComponentLabels& m_Regions;
  std::size_t m_Slice;
  std::vector<DisjointSets> m_Groups;
};

} // namespace

std::size_t enclosedCavities(const MaskVolume* mask, BackgroundConnectivity connectivity)
{
  std::vector<std::array<long, 3>> offsets;
  for (long dk = -1; dk <= 1; ++dk)
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di)
      {
        const int nonZero = (di != 0) + (dj != 0) + (dk != 0);
        const bool wanted = connectivity == BackgroundConnectivity::Faces6      ? nonZero == 1
                            : connectivity == BackgroundConnectivity::Corners26 ? nonZero >= 1
                                                                                 : nonZero == 1 || nonZero == 2;
        if (wanted)
          offsets.push_back({ di, dj, dk });
      }
  const auto size = mask->GetBufferedRegion().GetSize();
  const long nx = static_cast<long>(size[0]), ny = static_cast<long>(size[1]), nz = static_cast<long>(size[2]);
  const unsigned char* voxels = mask->GetBufferPointer();
  const bool slabAware = connectivity == BackgroundConnectivity::SliceContours;
  const ComponentLabels regions =
    slabAware ? labelComponents(mask, ProcessingDimension::Slice2D, 1, false) : ComponentLabels{};
  std::optional<SlabGroups> slabs;
  if (slabAware)
    slabs.emplace(regions, nx, ny, nz);
  auto at = [&](long i, long j, long k) { return (k * ny + j) * nx + i; };
  auto foreground = [&](long i, long j, long k)
  { return i >= 0 && j >= 0 && i < nx && j < ny && voxels[at(i, j, k)] != 0; };
  // The contour of slice k in the square of voxel centres (i, j) .. (i + 1, j + 1) (marching
  // squares at the 0.5 level; corners 0..3 counter-clockwise from (i, j), edge t from corner t to
  // corner t + 1): the other edge of the contour segment that crosses edge t there. Where the
  // foreground touches only at a corner (a saddle) the segments cut around each foreground corner,
  // as the contours are 4-connected.
  auto otherEdge = [&](long i, long j, long k, int t)
  {
    const bool v[4] = { foreground(i, j, k), foreground(i + 1, j, k), foreground(i + 1, j + 1, k),
                        foreground(i, j + 1, k) };
    auto crossed = [&](int e) { return v[e % 4] != v[(e + 1) % 4]; };
    if (crossed(0) && crossed(1) && crossed(2) && crossed(3))
      return v[t] ? (t + 3) % 4 : (t + 1) % 4; // around the foreground end of edge t
    for (int e = 1; e < 4; ++e)
      if (crossed((t + e) % 4))
        return (t + e) % 4;
    return t;
  };
  // A square whose foreground touches only at a corner: the background passes through its middle.
  auto saddle = [&](long i, long j, long k)
  {
    const bool v0 = foreground(i, j, k), v1 = foreground(i + 1, j, k);
    return v0 == foreground(i + 1, j + 1, k) && v1 == foreground(i, j + 1, k) && v0 != v1;
  };
  // Background voxels (x, y, z) and (a, b, c) across the slices at an edge are apart when the
  // other diagonal's voxels, (a, b, z) and (x, y, c), are foreground and tiled together, unless
  // in one of the two squares of voxel centres on either side of the edge the two slices' contour
  // segments through the edge's middle coincide (the two slices' background pieces share a
  // stretch of boundary and the slab's surface joins them there), or both slices have a saddle
  // there (a 2 x 2 x 2 checkerboard: the background runs through the square's middle from one
  // slice to the other). Where the contours only cross or touch at the edge's middle, the
  // background pieces stay apart.
  auto apartAcrossEdge = [&](long x, long y, long z, long a, long b, long c)
  {
    if (!foreground(a, b, z) || !foreground(x, y, c))
      return false;
    const long lower = std::min(z, c);
    if (!slabs->together(lower, z == lower ? at(a, b, z) : at(x, y, c), z == lower ? at(x, y, c) : at(a, b, z)))
      return false;
    // The squares whose edge t joins the columns (x, y) and (a, b): one on each side.
    const long i0 = std::min(x, a), j0 = std::min(y, b);
    const bool alongX = a != x; // the columns differ in i: the squares lie at j0 - 1 and j0
    const long squares[2][2] = { { alongX ? i0 : i0 - 1, alongX ? j0 - 1 : j0 }, { i0, j0 } };
    const int edges[2] = { alongX ? 2 : 1, alongX ? 0 : 3 };
    for (int n = 0; n < 2; ++n)
    {
      const long i = squares[n][0], j = squares[n][1];
      if (otherEdge(i, j, z, edges[n]) == otherEdge(i, j, c, edges[n]))
        return false;
      if (saddle(i, j, z) && saddle(i, j, c))
        return false;
    }
    return true;
  };

  std::vector<bool> seen(static_cast<std::size_t>(nx * ny * nz), false);
  std::vector<std::array<long, 3>> stack;
  std::size_t cavities = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
      {
        const long start = at(i, j, k);
        if (voxels[start] || seen[start])
          continue;
        // Flood this piece of background; it is open when it reaches a face of the region (the
        // region is at most the label's bounding box: beyond it everything is background).
        bool open = false;
        seen[start] = true;
        stack.push_back({ i, j, k });
        while (!stack.empty())
        {
          const auto [x, y, z] = stack.back();
          stack.pop_back();
          open = open || x == 0 || y == 0 || z == 0 || x + 1 == nx || y + 1 == ny || z + 1 == nz;
          for (const auto& d : offsets)
          {
            const long a = x + d[0], b = y + d[1], c = z + d[2];
            if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz)
              continue;
            const long n = at(a, b, c);
            if (voxels[n] || seen[n])
              continue;
            if (slabAware && d[2] != 0 && (d[0] != 0 || d[1] != 0) && apartAcrossEdge(x, y, z, a, b, c))
              continue;
            seen[n] = true;
            stack.push_back({ a, b, c });
          }
        }
        cavities += !open;
      }
  return cavities;
}

std::vector<double> componentVolumes(const TriangleMesh& mesh)
{
  DisjointSets pieces(mesh.points.size());
  for (const Triangle& t : mesh.triangles)
  {
    pieces.unite(t[0], t[1]);
    pieces.unite(t[0], t[2]);
  }
  std::map<std::size_t, double> volume; // by root: the smallest vertex index of the piece
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    // Signed volume of the tetrahedron (origin, a, b, c): the divergence theorem summed over a piece.
    volume[pieces.find(t[0])] +=
      (a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x)) / 6.0;
  }
  std::vector<double> result;
  for (const auto& [root, v] : volume)
    result.push_back(v);
  return result;
}

} // namespace slicemesh::testing

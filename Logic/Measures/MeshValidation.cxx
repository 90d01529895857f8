#include "Measures/MeshValidation.h"

#include "Core/AreaNormal.h"
#include "Core/DefaultInitAllocator.h"
#include "Core/ParallelFor.h"
#include "Core/DisjointSets.h"
#include "Core/MeasureText.h"
#include "Measures/ComponentOrientation.h"
#include "Measures/EdgeUses.h"
#include "Measures/MeshComponents.h"
#include "Measures/SelfIntersections.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>

namespace slicemesh
{
namespace
{

/** Triangles or vertices per range of the validation's parallel passes. */
constexpr std::size_t rangeSize = 8192;

/** Two triangles on one edge fold onto each other: their unit normals within a degree of opposite. */
bool folded(const std::array<float, 3>& m, const std::array<float, 3>& n)
{
  static const double foldCosine = std::cos(M_PI / 180.0);
  return static_cast<double>(m[0]) * n[0] + static_cast<double>(m[1]) * n[1] + static_cast<double>(m[2]) * n[2] <
         -foldCosine;
}

/** A triangle's unit normal in single precision (they only tell folds, far above its rounding);
 *  zero without area. `n`: its area normal, `twiceArea` that normal's length. */
std::array<float, 3> unitNormal(const Point3& n, double twiceArea)
{
  return twiceArea > 0.0 ? std::array<float, 3>{ static_cast<float>(n.x / twiceArea), static_cast<float>(n.y / twiceArea),
                                                 static_cast<float>(n.z / twiceArea) }
                         : std::array<float, 3>{ 0.0F, 0.0F, 0.0F };
}

std::array<float, 3> unitNormalOf(const TriangleMesh& mesh, std::size_t f)
{
  const Triangle& t = mesh.triangles[f];
  const Point3 n = areaNormal(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  return unitNormal(n, std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z));
}

/** What the points alone decide of a validation, triangle by triangle: degenerate triangles, area,
 *  smallest angles; and each triangle's unit normal into `normals` when given. On every core, in
 *  ranges fixed by the mesh, added in range order: the same sums whatever the threads. */
void measureTriangles(const TriangleMesh& mesh, MeshValidation& v, std::vector<std::array<float, 3>>* normals)
{
  const double cos30 = std::cos(M_PI / 6.0);
  const std::size_t nTriangles = mesh.triangles.size();
  struct TriangleSums
  {
    std::size_t degenerate = 0, below30 = 0;
    double area = 0.0, largestCosine = -1.0; // of the smallest angle of any triangle
  };
  const std::vector<TriangleSums> triangleSums = fixedRangeResults<TriangleSums>(
    nTriangles, rangeSize, 0,
    [&](TriangleSums& sums, std::size_t firstTriangle, std::size_t lastTriangle)
    {
      for (std::size_t f = firstTriangle; f < lastTriangle; ++f)
      {
        const Triangle& t = mesh.triangles[f];
        const Point3* p[3] = { &mesh.points[t[0]], &mesh.points[t[1]], &mesh.points[t[2]] };
        const Point3 n = areaNormal(*p[0], *p[1], *p[2]);
        const double twiceArea = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || twiceArea == 0.0)
          ++sums.degenerate;
        if (normals)
          (*normals)[f] = unitNormal(n, twiceArea);
        sums.area += 0.5 * twiceArea;
        const double cosine = smallestAngleCosine(*p[0], *p[1], *p[2]);
        sums.largestCosine = std::max(sums.largestCosine, cosine);
        sums.below30 += cosine > cos30;
      }
    });
  double largestCosine = -1.0;
  std::size_t below30 = 0;
  v.degenerateTriangles = 0;
  v.area = 0.0;
  for (const TriangleSums& sums : triangleSums)
  {
    v.degenerateTriangles += sums.degenerate;
    v.area += sums.area;
    largestCosine = std::max(largestCosine, sums.largestCosine);
    below30 += sums.below30;
  }
  v.minAngleDegrees = nTriangles == 0 ? 0.0 : std::acos(std::clamp(largestCosine, -1.0, 1.0)) * 180.0 / M_PI;
  v.fractionAnglesBelow30 = nTriangles == 0 ? 0.0 : static_cast<double>(below30) / static_cast<double>(nTriangles);
}

/** The volume and the components' orientation, once the rest of `v` is known. */
void measureVolumeAndOrientation(const TriangleMesh& mesh, MeshValidation& v)
{
  v.volume = signedVolume(mesh);
  v.misorientedComponents = 0;
  if (v.closed() && v.manifold() && v.inconsistentEdges == 0)
    v.misorientedComponents = v.components == 1 ? (v.volume > 0.0 ? 0 : 1) : misorientedComponents(mesh);
}

/** The folded edges among the edges of the triangles with a corner flagged in `moved`, on a closed
 *  mesh whose every edge has two triangles. Both triangles of such an edge have a corner among the
 *  corners of those triangles: only the triangles with one are gathered, and their edges sorted. */
std::size_t foldedEdgesAroundMoved(const TriangleMesh& mesh, const std::vector<char>& moved)
{
  if (std::none_of(moved.begin(), moved.end(), [](char flag) { return flag != 0; }))
    return 0;
  auto hasCornerIn = [](const std::vector<char>& flags, const Triangle& t)
  { return flags[static_cast<std::size_t>(t[0])] || flags[static_cast<std::size_t>(t[1])] || flags[static_cast<std::size_t>(t[2])]; };
  std::vector<char> near = moved;
  growByRings(mesh, near, 1); // the corners of the moved triangles
  // Each edge of the triangles with a corner near, keyed by its ends, with its triangle.
  struct EdgeOfTriangle
  {
    std::uint64_t key;
    std::uint32_t triangle;
    bool operator<(const EdgeOfTriangle& other) const
    {
      return key < other.key || (key == other.key && triangle < other.triangle);
    }
  };
  std::vector<EdgeOfTriangle> edges;
  for (const std::vector<EdgeOfTriangle>& range : fixedRangeResults<std::vector<EdgeOfTriangle>>(
         mesh.triangles.size(), rangeSize, 0,
         [&](std::vector<EdgeOfTriangle>& found, std::size_t first, std::size_t last)
         {
           for (std::size_t f = first; f < last; ++f)
           {
             const Triangle& t = mesh.triangles[f];
             if (!hasCornerIn(near, t))
               continue;
             for (int i = 0; i < 3; ++i)
             {
               const auto a = static_cast<std::uint32_t>(t[i]), b = static_cast<std::uint32_t>(t[(i + 1) % 3]);
               found.push_back({ static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b),
                                 static_cast<std::uint32_t>(f) });
             }
           }
         }))
    edges.insert(edges.end(), range.begin(), range.end());
  std::sort(edges.begin(), edges.end());
  std::size_t count = 0;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e)
  {
    if (edges[e].key != edges[e + 1].key)
      continue;
    const std::uint32_t f = edges[e].triangle, g = edges[e + 1].triangle;
    ++e;
    if (!hasCornerIn(moved, mesh.triangles[f]) && !hasCornerIn(moved, mesh.triangles[g]))
      continue; // neither moved: as it was
    count += folded(unitNormalOf(mesh, f), unitNormalOf(mesh, g));
  }
  return count;
}

} // namespace

std::string MeshValidation::summary() const
{
  std::ostringstream out;
  out << triangles << " triangles, " << (closed() ? "closed" : "open (" + std::to_string(boundaryEdges) + " boundary edges)")
      << ", " << (manifold() ? "manifold" : "non-manifold") << ", ";
  if (!selfIntersectionChecked)
    out << "self-intersections not checked";
  else if (selfIntersections == 0)
    out << "no self-intersections";
  else
    out << selfIntersections << " self-intersecting pairs";
  if (foldedEdges > 0)
    out << ", " << foldedEdges << " folded edges";
  if (inconsistentEdges > 0)
    out << ", " << inconsistentEdges << " edges wound against their neighbours";
  if (misorientedComponents > 0)
    out << ", " << misorientedComponents << (misorientedComponents == 1 ? " component" : " components")
        << " facing the wrong way";
  out << ", " << components << (components == 1 ? " component" : " components") << ", volume "
      << measureText(volume, 1) << " mm^3";
  return out.str();
}

MeshValidation validateMeshTopology(const TriangleMesh& mesh)
{
  // Linear in the triangles but for the sort of each vertex's few edges: no hash maps, no per-vertex
  // allocation, no inverse trigonometry per triangle (the cosine of its smallest angle; one arc
  // cosine at the end). The passes over triangles and over vertices run on every core, in ranges
  // fixed by the mesh alone, their counts and sums added in range order: the same result for any
  // number of threads.
  MeshValidation v;
  const std::size_t nTriangles = mesh.triangles.size();
  v.triangles = nTriangles;
  const std::size_t nPoints = mesh.points.size();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= nPoints)
        throw Error("mesh: a triangle refers to a vertex that does not exist");

  // Per triangle: degeneracy, area, unit normal, smallest angle.
  // A large piece's normals are held while its edges are gathered: single precision.
  std::vector<std::array<float, 3>> normals(nTriangles);
  measureTriangles(mesh, v, &normals);

  // Each vertex's corners (counting sort): the triangle and its two other corners in the triangle's
  // order. They tell both what a vertex decides and what its edges do. A vertex is manifold when its
  // triangles form one fan: the edges opposite it form one connected link. An edge is counted at its
  // lower end, whose corners hold every use of it (a triangle holding both ends has a corner at
  // each): the uses of one undirected edge tell boundary and non-manifold edges, their directions
  // orientation (two uses the same way), and their triangles' normals folds (against the edge's
  // first triangle). One pass over the corners, not a second table of every edge's uses.
  std::vector<std::size_t> start(nPoints + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t i : t)
      ++start[static_cast<std::size_t>(i) + 1];
  for (std::size_t p = 0; p < nPoints; ++p)
    start[p + 1] += start[p];
  struct Corner
  {
    std::int32_t next, previous; ///< the triangle's corners after this one and before it
    std::uint32_t triangle;
  };
  std::vector<Corner, DefaultInitAllocator<Corner>> corners(start[nPoints]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < nTriangles; ++f)
    {
      const Triangle& t = mesh.triangles[f];
      for (int i = 0; i < 3; ++i)
        corners[fill[static_cast<std::size_t>(t[i])]++] = { t[(i + 1) % 3], t[(i + 2) % 3], static_cast<std::uint32_t>(f) };
    }
  }
  struct VertexCounts
  {
    std::size_t edges = 0, folded = 0, inconsistent = 0, boundary = 0, nonManifold = 0, nonManifoldVertices = 0;
  };
  const std::vector<VertexCounts> vertexCounts = fixedRangeResults<VertexCounts>(
    nPoints, rangeSize, 0,
    [&](VertexCounts& counts, std::size_t firstPoint, std::size_t lastPoint)
    {
      std::vector<std::int32_t> local;
      std::vector<std::size_t> parent;
      std::vector<EdgeUse> uses;
      auto root = [&](std::size_t x)
      {
        while (parent[x] != x)
          x = parent[x] = parent[parent[x]];
        return x;
      };
      for (std::size_t p = firstPoint; p < lastPoint; ++p)
      {
        if (start[p] == start[p + 1])
          continue;
        const auto self = static_cast<std::int32_t>(p);
        local.clear();
        parent.clear();
        uses.clear();
        auto index = [&](std::int32_t vertex)
        {
          const auto at = std::find(local.begin(), local.end(), vertex);
          if (at != local.end())
            return static_cast<std::size_t>(at - local.begin());
          local.push_back(vertex);
          return local.size() - 1;
        };
        for (std::size_t c = start[p]; c < start[p + 1]; ++c)
        {
          const Corner& corner = corners[c];
          const std::size_t a = index(corner.next), b = index(corner.previous);
          while (parent.size() < local.size())
            parent.push_back(parent.size());
          const std::size_t ra = root(a), rb = root(b);
          if (ra != rb)
            parent[std::max(ra, rb)] = std::min(ra, rb);
          // The edge to the next corner runs from p; the one from the previous corner runs to p. An
          // edge from p to itself (a triangle with p twice) is one use, from the corner before it.
          if (corner.next >= self)
            uses.push_back({ corner.next, corner.triangle, corner.next > self });
          if (corner.previous > self)
            uses.push_back({ corner.previous, corner.triangle, false });
        }
        std::size_t fans = 0;
        for (std::size_t i = 0; i < local.size(); ++i)
          fans += root(i) == i;
        counts.nonManifoldVertices += fans > 1;
        // In the order of (other end, triangle): an edge's uses side by side, its first triangle first.
        std::sort(uses.begin(), uses.end());
        for (std::size_t first = 0; first < uses.size();)
        {
          std::size_t last = first + 1;
          std::size_t forward = uses[first].forward ? 1 : 0;
          const std::array<float, 3>& m = normals[uses[first].triangle];
          for (; last < uses.size() && uses[last].other == uses[first].other; ++last)
          {
            forward += uses[last].forward ? 1 : 0;
            counts.folded += folded(m, normals[uses[last].triangle]);
          }
          const std::size_t count = last - first, backward = count - forward;
          counts.inconsistent += (forward > 1 ? forward - 1 : 0) + (backward > 1 ? backward - 1 : 0);
          ++counts.edges;
          if (count == 1)
            ++counts.boundary;
          else if (count > 2)
            ++counts.nonManifold;
          first = last;
        }
      }
    });
  std::size_t edges = 0;
  for (const VertexCounts& counts : vertexCounts)
  {
    edges += counts.edges;
    v.foldedEdges += counts.folded;
    v.inconsistentEdges += counts.inconsistent;
    v.boundaryEdges += counts.boundary;
    v.nonManifoldEdges += counts.nonManifold;
    v.nonManifoldVertices += counts.nonManifoldVertices;
  }
  corners = decltype(corners)();
  normals = std::vector<std::array<float, 3>>();

  std::vector<char> used(nPoints, 0);
  DisjointSets pieces(nPoints);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
    {
      used[t[i]] = 1;
      pieces.unite(t[i], t[(i + 1) % 3]);
    }
  std::size_t usedCount = 0;
  for (std::size_t p = 0; p < nPoints; ++p)
    if (used[p])
    {
      ++usedCount;
      v.components += pieces.find(p) == p;
    }
  v.vertices = usedCount;
  measureVolumeAndOrientation(mesh, v);
  v.eulerCharacteristic =
    static_cast<long>(usedCount) - static_cast<long>(edges) + static_cast<long>(nTriangles);
  return v;
}

namespace
{

/** validateMeshTopology, and where the mesh is manifold and consistently oriented (the test needs
 *  it) the crossing pairs `crossingPairs()` finds; `crossings` gets them (empty when not tested). */
template <typename CrossingPairs>
MeshValidation validatedWith(const TriangleMesh& mesh, std::vector<std::pair<std::size_t, std::size_t>>& crossings,
                             CrossingPairs crossingPairs)
{
  MeshValidation v = validateMeshTopology(mesh);
  if (!(v.manifold() && v.inconsistentEdges == 0))
  {
    crossings.clear();
    return v;
  }
  crossings = crossingPairs();
  v.selfIntersections = crossings.size();
  v.selfIntersectionChecked = true;
  return v;
}

} // namespace

MeshValidation validateMesh(const TriangleMesh& mesh, std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  return validatedWith(mesh, crossings, [&] { return selfIntersectingTrianglePairs(mesh); });
}

MeshValidation validateMeshAfterMoving(const TriangleMesh& mesh, bool checkedBefore, const std::vector<char>& moved,
                                       std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  if (!checkedBefore)
    return validateMesh(mesh, crossings);
  return validatedWith(mesh, crossings,
                       [&] { return selfIntersectingTrianglePairsAfterMoving(mesh, crossings, moved); });
}

MeshValidation validateMeshAfterMovingPoints(const TriangleMesh& mesh, const MeshValidation& before,
                                             const std::vector<char>& moved,
                                             std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  // The triangles are as they were: their edges and vertices' fans, the components and the Euler
  // characteristic too. On a closed mesh with two triangles on every edge and no folds before, a
  // fold can only be new, on an edge of a moved triangle.
  const bool sameEdgesAsBefore = before.triangles == mesh.triangles.size() && moved.size() == mesh.points.size() &&
                                 before.closed() && before.manifold() && before.inconsistentEdges == 0 &&
                                 before.foldedEdges == 0;
  if (!sameEdgesAsBefore)
    return validateMeshAfterMoving(mesh, before.selfIntersectionChecked, moved, crossings);
  MeshValidation v = before;
  measureTriangles(mesh, v, nullptr);
  v.foldedEdges = foldedEdgesAroundMoved(mesh, moved);
  measureVolumeAndOrientation(mesh, v);
  crossings = before.selfIntersectionChecked ? selfIntersectingTrianglePairsAfterMoving(mesh, crossings, moved)
                                             : selfIntersectingTrianglePairs(mesh);
  v.selfIntersections = crossings.size();
  v.selfIntersectionChecked = true;
  return v;
}

MeshValidation validateMesh(const TriangleMesh& mesh)
{
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  return validateMesh(mesh, crossings);
}

MeshValidation joinedValidation(const std::vector<MeshValidation>& parts, std::size_t crossingPairs)
{
  MeshValidation v;
  v.selfIntersectionChecked = true;
  double below30 = 0.0;
  v.minAngleDegrees = parts.empty() ? 0.0 : 180.0;
  for (const MeshValidation& p : parts)
  {
    v.vertices += p.vertices;
    v.triangles += p.triangles;
    v.degenerateTriangles += p.degenerateTriangles;
    v.boundaryEdges += p.boundaryEdges;
    v.nonManifoldEdges += p.nonManifoldEdges;
    v.nonManifoldVertices += p.nonManifoldVertices;
    v.inconsistentEdges += p.inconsistentEdges;
    v.misorientedComponents += p.misorientedComponents;
    v.foldedEdges += p.foldedEdges;
    v.selfIntersections += p.selfIntersections;
    v.selfIntersectionChecked = v.selfIntersectionChecked && p.selfIntersectionChecked;
    v.components += p.components;
    v.eulerCharacteristic += p.eulerCharacteristic;
    v.area += p.area;
    v.volume += p.volume;
    v.minAngleDegrees = std::min(v.minAngleDegrees, p.minAngleDegrees);
    below30 += p.fractionAnglesBelow30 * static_cast<double>(p.triangles);
  }
  v.selfIntersections += crossingPairs;
  v.fractionAnglesBelow30 = v.triangles > 0 ? below30 / static_cast<double>(v.triangles) : 0.0;
  return v;
}

double signedVolume(const TriangleMesh& mesh)
{
  double volume = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3& a = mesh.points[t[0]];
    const Point3& b = mesh.points[t[1]];
    const Point3& c = mesh.points[t[2]];
    volume += (a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x)) / 6.0;
  }
  return volume;
}

std::vector<std::pair<std::size_t, std::size_t>> selfIntersectingPairs(const TriangleMesh& mesh)
{
  return selfIntersectingTrianglePairs(mesh);
}

} // namespace slicemesh

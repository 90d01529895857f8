#include "Measures/MeshValidation.h"

#include "Core/AreaNormal.h"
#include "Core/ParallelFor.h"
#include "Core/DisjointSets.h"
#include "Core/MeasureText.h"
#include "Measures/ComponentOrientation.h"
#include "Measures/MeshComponents.h"
#include "Measures/SelfIntersections.h"
#include "Measures/TriangleAngles.h"
#include "Measures/VertexFans.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace slicemesh
{
namespace
{

/** Triangles or vertices per range of the validation's parallel passes. */
constexpr std::size_t rangeSize = 8192;

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

/** The edges' and fans' counts of a validation. */
void setEdgeCounts(MeshValidation& v, const FanCounts& counts)
{
  v.foldedEdges = counts.folded;
  v.inconsistentEdges = counts.inconsistent;
  v.boundaryEdges = counts.boundary;
  v.nonManifoldEdges = counts.nonManifold;
  v.nonManifoldVertices = counts.nonManifoldVertices;
}

/** `v` completed, its triangles' and edges' counts known (`edges`: how many): the vertices in use,
 *  the components, the volume and orientation, the Euler characteristic. */
MeshValidation withComponentsAndVolume(const TriangleMesh& mesh, MeshValidation v, std::size_t edges)
{
  const std::size_t nPoints = mesh.points.size();
  std::vector<char> used(nPoints, 0);
  DisjointSets pieces(nPoints);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
    {
      used[t[i]] = 1;
      pieces.unite(t[i], t[(i + 1) % 3]);
    }
  std::size_t usedCount = 0;
  v.components = 0;
  for (std::size_t p = 0; p < nPoints; ++p)
    if (used[p])
    {
      ++usedCount;
      v.components += pieces.find(p) == p;
    }
  v.vertices = usedCount;
  measureVolumeAndOrientation(mesh, v);
  v.eulerCharacteristic =
    static_cast<long>(usedCount) - static_cast<long>(edges) + static_cast<long>(mesh.triangles.size());
  return v;
}

/** Whether every edge of the validated mesh had two triangles, wound against each other and not
 *  folded, and every vertex one fan: what the validations after a change take as known elsewhere. */
bool pairedWithoutFolds(const MeshValidation& v)
{
  return v.closed() && v.manifold() && v.inconsistentEdges == 0 && v.foldedEdges == 0;
}

/** Throws unless every corner of every triangle is a vertex of the mesh. */
void checkCorners(const TriangleMesh& mesh)
{
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= mesh.points.size())
        throw Error("mesh: a triangle refers to a vertex that does not exist");
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
    count += foldedNormals(unitNormalOf(mesh, f), unitNormalOf(mesh, g));
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
  checkCorners(mesh);

  // Per triangle: degeneracy, area, unit normal, smallest angle.
  // A large piece's normals are held while its edges are gathered: single precision.
  std::vector<std::array<float, 3>> normals(nTriangles);
  measureTriangles(mesh, v, &normals);

  // Each vertex's corners (counting sort), each vertex then tallied from its own (VertexFans): its
  // fan, and the edges it is the lower end of. One pass over the corners, not a second table of every
  // edge's uses.
  CornersBySlot filed = cornersBySlot(mesh, nPoints, [](std::int32_t v) { return v; });
  FanCounts counts;
  for (const FanCounts& range : fixedRangeResults<FanCounts>(
         nPoints, rangeSize, 0,
         [&](FanCounts& rangeCounts, std::size_t firstPoint, std::size_t lastPoint)
         {
           VertexFanTally tally;
           for (std::size_t p = firstPoint; p < lastPoint; ++p)
           {
             const auto self = static_cast<std::int32_t>(p);
             tally.tally(
               self, filed.corners.data() + filed.start[p], filed.corners.data() + filed.start[p + 1],
               [self](std::int32_t w) { return w >= self; },
               [&](std::uint32_t f) -> const std::array<float, 3>& { return normals[f]; }, rangeCounts);
           }
         }))
    counts += range;
  filed = CornersBySlot();
  normals = std::vector<std::array<float, 3>>();
  setEdgeCounts(v, counts);
  return withComponentsAndVolume(mesh, v, counts.edges);
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
                                 pairedWithoutFolds(before);
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

MeshValidation validateMeshAfterLocalChange(const TriangleMesh& mesh, const MeshValidation& before,
                                            const std::vector<char>& changed,
                                            std::vector<std::pair<std::size_t, std::size_t>>& crossings)
{
  crossings.clear(); // numbered as before the change: none carries over
  if (!(before.selfIntersectionChecked && before.selfIntersections == 0 && changed.size() == mesh.points.size()))
    return validateMesh(mesh, crossings);
  // The triangles left as they were cross nothing among themselves still: only those with a changed
  // corner are tested. Where an edge was not paired or was folded before, the edges are gathered whole.
  if (!pairedWithoutFolds(before))
    return validateMeshAfterMoving(mesh, true, changed, crossings);
  checkCorners(mesh);
  MeshValidation v;
  v.triangles = mesh.triangles.size();
  measureTriangles(mesh, v, nullptr);
  // The changed vertices' corners (counting sort over a list of them), each vertex tallied from its
  // own: its fan, and its edges but those to a changed vertex below it (counted there).
  std::vector<std::int32_t> changedVertices, slotOf(mesh.points.size(), -1);
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    if (changed[p])
    {
      slotOf[p] = static_cast<std::int32_t>(changedVertices.size());
      changedVertices.push_back(static_cast<std::int32_t>(p));
    }
  const CornersBySlot filed = cornersBySlot(mesh, changedVertices.size(),
                                            [&](std::int32_t vertex) { return slotOf[static_cast<std::size_t>(vertex)]; });
  FanCounts counts;
  VertexFanTally tally;
  for (std::size_t s = 0; s < changedVertices.size(); ++s)
  {
    const std::int32_t self = changedVertices[s];
    tally.tally(
      self, filed.corners.data() + filed.start[s], filed.corners.data() + filed.start[s + 1],
      [&](std::int32_t w) { return w >= self || !changed[static_cast<std::size_t>(w)]; },
      [&](std::uint32_t f) { return unitNormalOf(mesh, f); }, counts);
  }
  // Every edge not counted has its two uses of before: the uses add up to three per triangle. An
  // odd remainder can only come from a `changed` that misses a changed edge (not every such miss
  // gives one): the whole check then, a cheap guard, not a test of the contract.
  const std::size_t uses = 3 * mesh.triangles.size();
  if (counts.edgeUses > uses || (uses - counts.edgeUses) % 2 != 0)
    return validateMesh(mesh, crossings);
  setEdgeCounts(v, counts);
  v = withComponentsAndVolume(mesh, v, counts.edges + (uses - counts.edgeUses) / 2);
  if (!(v.manifold() && v.inconsistentEdges == 0))
    return v; // as validateMesh: no crossing test of a mesh it cannot judge
  crossings = selfIntersectingTrianglePairsAfterMoving(mesh, crossings, changed);
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

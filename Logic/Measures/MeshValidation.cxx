#include "Measures/MeshValidation.h"

#include "Core/DisjointSets.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace slicemesh
{

namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

std::uint64_t directedKey(std::int32_t a, std::int32_t b)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

double angleAt(const Point3& o, const Point3& p, const Point3& q)
{
  const double ux = p.x - o.x, uy = p.y - o.y, uz = p.z - o.z;
  const double vx = q.x - o.x, vy = q.y - o.y, vz = q.z - o.z;
  const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz);
}

/** Counts pairs of triangles that intersect other than along the vertices and edges they share. */
/** The self-intersecting pairs by face index (faces are added in the order of mesh.triangles, so a
 *  face's index is its triangle's); `checked` false when CGAL cannot hold the mesh as a surface. */
std::vector<std::pair<std::size_t, std::size_t>> intersectingPairs(const TriangleMesh& mesh, bool& checked)
{
  SurfaceMesh surface;
  std::vector<SurfaceMesh::Vertex_index> handles;
  handles.reserve(mesh.points.size());
  for (const Point3& p : mesh.points)
    handles.push_back(surface.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
  for (const Triangle& t : mesh.triangles)
    if (surface.add_face(handles[t[0]], handles[t[1]], handles[t[2]]) == SurfaceMesh::null_face())
    {
      checked = false;
      return {};
    }
  // On every core (TBB): the pairs come in no fixed order, so they are sorted.
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(surface, std::back_inserter(pairs));
  checked = true;
  std::vector<std::pair<std::size_t, std::size_t>> result;
  result.reserve(pairs.size());
  for (const auto& [first, second] : pairs)
  {
    const auto a = static_cast<std::size_t>(first.idx()), b = static_cast<std::size_t>(second.idx());
    result.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(result.begin(), result.end());
  return result;
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
  out << ", " << components << (components == 1 ? " component" : " components") << ", volume " << std::fixed
      << std::setprecision(1) << volume << " mm^3";
  return out.str();
}

MeshValidation validateMeshTopology(const TriangleMesh& mesh)
{
  const double foldCosine = std::cos(M_PI / 180.0); // a dihedral angle under 1 degree
  MeshValidation v;
  v.triangles = mesh.triangles.size();
  const std::size_t nPoints = mesh.points.size();
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= nPoints)
        throw Error("mesh: a triangle refers to a vertex that does not exist");

  // Edges: directed uses tell orientation, undirected counts tell boundary and non-manifold edges
  // (and each undirected edge's first triangle, whose normal a second one is compared with: folds).
  std::unordered_map<std::uint64_t, int> directed;
  struct EdgeUse
  {
    int count = 0;
    std::size_t firstTriangle = 0;
  };
  std::unordered_map<std::uint64_t, EdgeUse> undirected;
  std::vector<char> used(nPoints, 0);
  DisjointSets pieces(nPoints);
  double minAngle = M_PI;
  std::size_t below30 = 0;
  std::vector<std::array<double, 3>> normals;
  normals.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    const Point3& a = mesh.points[t[0]];
    const Point3& b = mesh.points[t[1]];
    const Point3& c = mesh.points[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
    const double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
    const double twiceArea = std::sqrt(cx * cx + cy * cy + cz * cz);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || twiceArea == 0.0)
      ++v.degenerateTriangles;
    normals.push_back(twiceArea > 0.0 ? std::array<double, 3>{ cx / twiceArea, cy / twiceArea, cz / twiceArea }
                                      : std::array<double, 3>{ 0.0, 0.0, 0.0 });
    v.area += 0.5 * twiceArea;
    const double smallest = std::min({ angleAt(a, b, c), angleAt(b, c, a), angleAt(c, a, b) });
    minAngle = std::min(minAngle, smallest);
    if (smallest < M_PI / 6.0)
      ++below30;
    for (int i = 0; i < 3; ++i)
    {
      const std::int32_t p = t[i], q = t[(i + 1) % 3];
      ++directed[directedKey(p, q)];
      EdgeUse& use = undirected[directedKey(std::min(p, q), std::max(p, q))];
      if (++use.count == 1)
        use.firstTriangle = normals.size() - 1;
      else
      { // unit normals nearly opposite: the triangles lie on top of each other
        const std::array<double, 3>& m = normals[use.firstTriangle];
        const std::array<double, 3>& n = normals.back();
        if (m[0] * n[0] + m[1] * n[1] + m[2] * n[2] < -foldCosine)
          ++v.foldedEdges;
      }
      used[p] = 1;
      pieces.unite(p, q);
    }
  }
  for (const auto& [key, count] : directed)
    if (count > 1)
      v.inconsistentEdges += count - 1;
  for (const auto& [key, use] : undirected)
  {
    if (use.count == 1)
      ++v.boundaryEdges;
    else if (use.count > 2)
      ++v.nonManifoldEdges;
  }

  // A vertex is manifold when its triangles form one fan: the edges opposite it form one connected link.
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> links(nPoints);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      links[t[i]].emplace_back(t[(i + 1) % 3], t[(i + 2) % 3]);
  for (std::size_t p = 0; p < nPoints; ++p)
  {
    if (links[p].empty())
      continue;
    std::map<std::int32_t, std::size_t> local;
    for (const auto& [a, b] : links[p])
    {
      local.emplace(a, local.size());
      local.emplace(b, local.size());
    }
    DisjointSets fan(local.size());
    for (const auto& [a, b] : links[p])
      fan.unite(local[a], local[b]);
    std::size_t fans = 0;
    for (std::size_t i = 0; i < local.size(); ++i)
      fans += fan.find(i) == i;
    if (fans > 1)
      ++v.nonManifoldVertices;
  }

  std::size_t usedCount = 0;
  for (std::size_t p = 0; p < nPoints; ++p)
    if (used[p])
    {
      ++usedCount;
      v.components += pieces.find(p) == p;
    }
  v.vertices = usedCount;
  v.volume = signedVolume(mesh);
  v.eulerCharacteristic =
    static_cast<long>(usedCount) - static_cast<long>(undirected.size()) + static_cast<long>(mesh.triangles.size());
  v.minAngleDegrees = mesh.triangles.empty() ? 0.0 : minAngle * 180.0 / M_PI;
  v.fractionAnglesBelow30 = mesh.triangles.empty() ? 0.0 : static_cast<double>(below30) / mesh.triangles.size();

  return v;
}

MeshValidation validateMesh(const TriangleMesh& mesh)
{
  MeshValidation v = validateMeshTopology(mesh);
  if (v.manifold() && v.inconsistentEdges == 0)
    v.selfIntersections = intersectingPairs(mesh, v.selfIntersectionChecked).size();
  return v;
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
  bool checked = false;
  return intersectingPairs(mesh, checked);
}

} // namespace slicemesh

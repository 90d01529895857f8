// Steps 4 and 5 of Documentation/Algorithm.md, the output: the lifted triangles of the difference
// polygons, the vertical fans where the surface switches slices at a common vertex, and the walls where
// the two slices' contours coincide.
#include "Tiling/SlabOverlayState.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

using namespace slab;

void SlabOverlay::Impl::emitTriangles(MeshBuilder& mesh, int rows, ReconstructionStatistics& statistics)
{
  // Where the surface switches from one slice to the other at a vertex common to both, the rise is
  // spread over the sector's fan: each face takes the node of the vertex's vertical chain nearest the
  // height of its Steiner corners, and each fan edge where consecutive faces differ carries a small
  // vertical fan over the chain nodes between them (one tall fan from a single point would be slivers).
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    f->info().cornerLevel = { NoLevel, NoLevel, NoLevel };
    f->info().cornerId = { -1, -1, -1 };
  }
  struct Switch
  {
    std::int32_t far;                 ///< the fan edge's Steiner end
    FaceHandle before;                ///< the face on the start side of the fan edge
    std::vector<std::int32_t> nodes;  ///< chain nodes climbed, in the direction from start to end
  };
  std::map<int, std::vector<std::int32_t>> chains;
  std::vector<Switch> switches;
  for (const Sector& s : mixedSectors(true))
  {
    std::vector<std::int32_t> chain = wallChain(s.vertex->info(), chains, rows, mesh);
    if (s.startLevel == UpperLevel)
      std::reverse(chain.begin(), chain.end());
    const int n = static_cast<int>(chain.size()) - 1;
    const double zStart = mesh.point(chain.front()).z, zEnd = mesh.point(chain.back()).z;
    auto fraction = [&](VertexHandle w) {
      return std::clamp((mesh.point(vertices[w->info()].steinerId).z - zStart) / (zEnd - zStart), 0.0, 1.0);
    };
    const std::size_t faces = s.faces.size();
    std::vector<int> node(faces, 0);
    node.back() = n;
    for (std::size_t k = 1; k + 1 < faces; ++k)
      node[k] = std::clamp(static_cast<int>(std::lround(0.5 * (fraction(s.fan[k - 1]) + fraction(s.fan[k])) * n)),
                           node[k - 1], n);
    for (std::size_t k = 0; k < faces; ++k)
      s.faces[k]->info().cornerId[s.faces[k]->index(s.vertex)] = chain[node[k]];
    for (std::size_t k = 0; k + 1 < faces; ++k)
      if (node[k] != node[k + 1])
        switches.push_back({ vertices[s.fan[k]->info()].steinerId, s.faces[k],
                             std::vector<std::int32_t>(chain.begin() + node[k], chain.begin() + node[k + 1] + 1) });
  }

  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!isDifference(f))
      continue;
    const Component& c = components[f->info().component];
    std::array<std::int32_t, 3> ids;
    for (int i = 0; i < 3; ++i)
    {
      const OverlayVertex& v = vertices[f->vertex(i)->info()];
      if (v.isSteiner())
        ids[i] = v.steinerId;
      else if (c.isCap())
        ids[i] = c.capLevel() == LowerLevel ? v.lowerId : v.upperId;
      else if (!v.onBoth())
        ids[i] = v.lowerId >= 0 ? v.lowerId : v.upperId;
      else if (f->info().cornerId[i] >= 0)
        ids[i] = f->info().cornerId[i];
      else
      {
        const signed char level = f->info().cornerLevel[i];
        if (level == NoLevel)
          throw Error("tiling: a vertex common to both slices has no level (internal error)");
        ids[i] = level == LowerLevel ? v.lowerId : v.upperId;
      }
    }
    // Counter-clockwise seen from above faces up: right for lower \ upper (solid below).
    if (!c.lowerSide)
      std::swap(ids[1], ids[2]);
    f->info().lifted = ids;
    mesh.addTriangle(ids[0], ids[1], ids[2]);
    ++(c.isCap() ? statistics.capTriangles : statistics.tilingTriangles);
  }

  // The vertical fans, wound to match the face before them.
  for (const Switch& s : switches)
  {
    const auto& t = s.before->info().lifted;
    bool farToVertex = false; // whether the face before the switch runs far -> nodes[0]
    for (int i = 0; i < 3; ++i)
      if (t[i] == s.far && t[(i + 1) % 3] == s.nodes.front())
        farToVertex = true;
    for (std::size_t r = 0; r + 1 < s.nodes.size(); ++r)
    {
      if (farToVertex)
        mesh.addTriangle(s.nodes[r], s.far, s.nodes[r + 1]);
      else
        mesh.addTriangle(s.far, s.nodes[r], s.nodes[r + 1]);
      ++statistics.wallTriangles;
    }
  }

  // Walls where the two slices' contours coincide and run the same way.
  for (const auto& [key, e] : edges)
  {
    (void)key;
    if (!(e.lower && e.upper && e.lowerFrom == e.upperFrom))
      continue;
    const int from = e.lowerFrom;
    const int to = static_cast<int>(key >> 32) == from ? static_cast<int>(key & 0xffffffffULL)
                                                        : static_cast<int>(key >> 32);
    addWallStrip(wallChain(from, chains, rows, mesh), wallChain(to, chains, rows, mesh), mesh,
                   statistics.wallTriangles);
  }
}

std::vector<std::int32_t> SlabOverlay::Impl::wallChain(int vertex, std::map<int, std::vector<std::int32_t>>& chains,
                                                       int rows, MeshBuilder& mesh) const
{
  // The vertical edge at a vertex common to both slices, cut into rows, bottom to top.
  auto it = chains.find(vertex);
  if (it != chains.end())
    return it->second;
  const OverlayVertex& v = vertices[vertex];
  std::vector<std::int32_t> chain{ v.lowerId };
  const Point3 bottom = mesh.point(v.lowerId);
  const Point3 top = mesh.point(v.upperId);
  for (int r = 1; r < rows; ++r)
  {
    const double t = static_cast<double>(r) / rows;
    chain.push_back(mesh.addPoint(bottom.x + t * (top.x - bottom.x), bottom.y + t * (top.y - bottom.y),
                                  bottom.z + t * (top.z - bottom.z)));
  }
  chain.push_back(v.upperId);
  chains[vertex] = chain;
  return chain;
}

void SlabOverlay::Impl::addWallStrip(const std::vector<std::int32_t>& from, const std::vector<std::int32_t>& to,
                                     MeshBuilder& mesh, std::size_t& counter) const
{
  // A vertical strip along a contour edge from -> to (solid on the left), both chains bottom to top:
  // its triangles face away from the solid.
  for (std::size_t r = 0; r + 1 < from.size(); ++r)
  {
    mesh.addTriangle(from[r], to[r], to[r + 1]);
    mesh.addTriangle(from[r], to[r + 1], from[r + 1]);
    counter += 2;
  }
}

} // namespace slicemesh

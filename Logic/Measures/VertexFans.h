// What the triangles around one vertex tell of a mesh's topology: whether they form one fan, and how
// the edges at the vertex are used (boundary, non-manifold, wound against each other, folded). The
// whole topology check (MeshValidation) and its check after a local change tally vertices alike.
#ifndef VertexFans_h
#define VertexFans_h

#include "Core/DefaultInitAllocator.h"
#include "Core/SliceMeshTypes.h"
#include "Measures/EdgeUses.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace slicemesh
{

/** One triangle's corner at a vertex: the triangle and its two other corners in the triangle's order. */
struct VertexCorner
{
  std::int32_t next, previous;
  std::uint32_t triangle;
};

/** Corners filed by slot: slot s's are corners[start[s]] .. corners[start[s + 1] - 1], in triangle order. */
struct CornersBySlot
{
  std::vector<std::size_t> start;
  std::vector<VertexCorner, DefaultInitAllocator<VertexCorner>> corners;
};

/** The corners of the vertices of `mesh` that have a slot (slotOf(vertex): below `slots`, or -1 for a
 *  vertex left out), filed by slot in two passes over the triangles (counting sort). */
template <typename SlotOf>
CornersBySlot cornersBySlot(const TriangleMesh& mesh, std::size_t slots, SlotOf&& slotOf)
{
  CornersBySlot filed;
  filed.start.assign(slots + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (std::int32_t v : t)
      if (const std::int32_t slot = slotOf(v); slot >= 0)
        ++filed.start[static_cast<std::size_t>(slot) + 1];
  for (std::size_t s = 0; s < slots; ++s)
    filed.start[s + 1] += filed.start[s];
  filed.corners.resize(filed.start[slots]);
  std::vector<std::size_t> fill(filed.start.begin(), filed.start.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
      if (const std::int32_t slot = slotOf(t[i]); slot >= 0)
        filed.corners[fill[static_cast<std::size_t>(slot)]++] = { t[(i + 1) % 3], t[(i + 2) % 3],
                                                                  static_cast<std::uint32_t>(f) };
  }
  return filed;
}

/** Counts over the vertices tallied and the edges they counted. */
struct FanCounts
{
  std::size_t edges = 0, edgeUses = 0, folded = 0, inconsistent = 0, boundary = 0, nonManifold = 0,
              nonManifoldVertices = 0;
  FanCounts& operator+=(const FanCounts& other);
};

/** Two triangles on one edge fold onto each other: their unit normals within a degree of opposite. */
bool foldedNormals(const std::array<float, 3>& m, const std::array<float, 3>& n);

/** Tallies vertices one at a time, reusing its scratch lists (one tally per thread). */
class VertexFanTally
{
public:
  /** Vertex `self`, its corners [first, last) (every triangle holding it, one corner for each time it
   *  holds it), into `counts`: one more non-manifold vertex if its triangles form more than one fan
   *  (the edges opposite it, its link, fall apart), and the edges from it to each w with
   *  countsEdgeTo(w), each once (a triangle holding both ends of an edge has a corner at each, so
   *  the corners of either end hold every use of it). An edge from `self` to itself (a triangle
   *  holding it twice) is one use. Each edge's uses are taken in the order of their triangles: folds
   *  are told against the first (normalOf(triangle): its unit normal), as EdgeUses orders them. */
  template <typename CountsEdgeTo, typename NormalOf>
  void tally(std::int32_t self, const VertexCorner* first, const VertexCorner* last, CountsEdgeTo&& countsEdgeTo,
             NormalOf&& normalOf, FanCounts& counts)
  {
    m_Uses.clear();
    for (const VertexCorner* corner = first; corner != last; ++corner)
    {
      // The edge to the next corner runs from `self`, the one from the previous corner runs to it.
      if (countsEdgeTo(corner->next))
        m_Uses.push_back({ corner->next, corner->triangle, self < corner->next });
      if (corner->previous != self && countsEdgeTo(corner->previous))
        m_Uses.push_back({ corner->previous, corner->triangle, corner->previous < self });
    }
    counts.nonManifoldVertices += fans(first, last) > 1;
    countEdges(normalOf, counts);
  }

private:
  std::size_t fans(const VertexCorner* first, const VertexCorner* last);

  template <typename NormalOf>
  void countEdges(NormalOf&& normalOf, FanCounts& counts)
  {
    std::sort(m_Uses.begin(), m_Uses.end());
    counts.edgeUses += m_Uses.size();
    for (std::size_t begin = 0; begin < m_Uses.size();)
    {
      std::size_t end = begin + 1, forward = m_Uses[begin].forward ? 1 : 0;
      const std::array<float, 3> m = normalOf(m_Uses[begin].triangle);
      for (; end < m_Uses.size() && m_Uses[end].other == m_Uses[begin].other; ++end)
      {
        forward += m_Uses[end].forward ? 1 : 0;
        counts.folded += foldedNormals(m, normalOf(m_Uses[end].triangle));
      }
      const std::size_t uses = end - begin, backward = uses - forward;
      counts.inconsistent += (forward > 1 ? forward - 1 : 0) + (backward > 1 ? backward - 1 : 0);
      ++counts.edges;
      if (uses == 1)
        ++counts.boundary;
      else if (uses > 2)
        ++counts.nonManifold;
      begin = end;
    }
  }

  std::vector<EdgeUse> m_Uses;
  std::vector<std::int32_t> m_Link;  ///< the link's vertices
  std::vector<std::size_t> m_Parent; ///< union-find over them
};

} // namespace slicemesh

#endif

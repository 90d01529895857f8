// Every use of an edge by a triangle, gathered by the edge's lower vertex: what the measures need to
// tell an edge's triangles apart (boundary, non-manifold, wound against each other, a flip's two
// triangles) without a hash map or one sort of every edge of the mesh.
#ifndef EdgeUses_h
#define EdgeUses_h

#include "Core/DefaultInitAllocator.h"
#include "Core/SliceMeshTypes.h"

#include <cstdint>
#include <vector>

namespace slicemesh
{

/** One triangle's use of an edge, filed under the edge's lower vertex. */
struct EdgeUse
{
  std::int32_t other;     ///< the edge's higher vertex
  std::uint32_t triangle; ///< the triangle using it
  bool forward;           ///< the triangle runs from the lower vertex to the higher
  bool operator<(const EdgeUse& e) const
  {
    return other != e.other ? other < e.other : (triangle != e.triangle ? triangle < e.triangle : forward < e.forward);
  }
};

/** The uses of every edge of a mesh: vertex v's, uses()[first(v)] .. uses()[first(v + 1)] - 1, in
 *  increasing order, so the uses of one edge stand together and the edges come in the order a sort
 *  of every edge would give. Counted into place by the lower vertex, then each vertex's few sorted,
 *  the vertices side by side on `threads` threads (the same order for any number). */
class EdgeUses
{
public:
  EdgeUses(const TriangleMesh& mesh, unsigned int threads);

  std::size_t vertices() const { return m_First.size() - 1; }
  std::size_t first(std::size_t v) const { return m_First[v]; }
  const std::vector<EdgeUse, DefaultInitAllocator<EdgeUse>>& uses() const { return m_Uses; }

  /** Calls visit(first, last) for each edge filed under vertex v, in order: [first, last) are its
   *  uses (pointers into uses()). */
  template <typename Visit>
  void forEachEdgeOf(std::size_t v, Visit&& visit) const
  {
    const EdgeUse* const end = m_Uses.data() + m_First[v + 1];
    for (const EdgeUse* first = m_Uses.data() + m_First[v]; first != end;)
    {
      const EdgeUse* last = first + 1;
      while (last != end && last->other == first->other)
        ++last;
      visit(first, last);
      first = last;
    }
  }

  /** Whether some triangle uses the edge between a and b. */
  bool contains(std::int32_t a, std::int32_t b) const;

private:
  std::vector<std::size_t> m_First;
  std::vector<EdgeUse, DefaultInitAllocator<EdgeUse>> m_Uses; ///< sized, then filled on every thread
};

} // namespace slicemesh

#endif

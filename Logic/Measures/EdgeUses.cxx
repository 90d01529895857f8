#include "Measures/EdgeUses.h"

#include "Core/ParallelFor.h"

#include <algorithm>

namespace slicemesh
{

EdgeUses::EdgeUses(const TriangleMesh& mesh, unsigned int threads)
  : m_First(mesh.points.size() + 1, 0)
{
  // Counted and filed by lower vertex, each thread for its own range of vertices (every thread
  // reads every triangle, writes only its vertices' slots): the uses of a vertex are filed in
  // triangle order whatever the number of threads, and no count is shared.
  const std::size_t vertexCount = mesh.points.size();
  const std::size_t workers =
    mesh.triangles.size() < 65536 ? 1 : std::min<std::size_t>(threadCount(threads), 8);
  auto forOwnUses = [&](std::size_t w, auto&& use)
  {
    const auto low = static_cast<std::int64_t>(vertexCount * w / workers);
    const auto high = static_cast<std::int64_t>(vertexCount * (w + 1) / workers);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    {
      const Triangle& t = mesh.triangles[f];
      for (int i = 0; i < 3; ++i)
      {
        const std::int32_t p = t[i], q = t[(i + 1) % 3], lower = std::min(p, q);
        if (lower >= low && lower < high)
          use(f, p, q, lower);
      }
    }
  };
  parallelFor(workers, threads,
              [&](std::size_t w)
              {
                forOwnUses(w, [&](std::size_t, std::int32_t, std::int32_t, std::int32_t lower)
                           { ++m_First[static_cast<std::size_t>(lower) + 1]; });
              });
  for (std::size_t v = 0; v < vertexCount; ++v)
    m_First[v + 1] += m_First[v];
  m_Uses.resize(m_First.back());
  std::vector<std::size_t> next(m_First.begin(), m_First.end() - 1);
  parallelFor(workers, threads,
              [&](std::size_t w)
              {
                forOwnUses(w,
                           [&](std::size_t f, std::int32_t p, std::int32_t q, std::int32_t lower)
                           {
                             m_Uses[next[static_cast<std::size_t>(lower)]++] = { std::max(p, q), static_cast<std::uint32_t>(f),
                                                                                 p < q };
                           });
              });
  parallelForRanges(vertices(), threads,
                    [&](std::size_t firstVertex, std::size_t lastVertex)
                    {
                      for (std::size_t v = firstVertex; v < lastVertex; ++v)
                        std::sort(m_Uses.begin() + static_cast<std::ptrdiff_t>(m_First[v]),
                                  m_Uses.begin() + static_cast<std::ptrdiff_t>(m_First[v + 1]));
                    });
}

bool EdgeUses::contains(std::int32_t a, std::int32_t b) const
{
  const auto low = static_cast<std::size_t>(std::min(a, b));
  const std::int32_t high = std::max(a, b);
  for (std::size_t u = m_First[low]; u < m_First[low + 1]; ++u)
    if (m_Uses[u].other == high)
      return true;
  return false;
}

} // namespace slicemesh

#include "Measures/EdgeUses.h"

#include "Core/ParallelFor.h"

#include <algorithm>

namespace slicemesh
{

EdgeUses::EdgeUses(const TriangleMesh& mesh, unsigned int threads)
  : m_First(mesh.points.size() + 1, 0)
{
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++m_First[static_cast<std::size_t>(std::min(t[i], t[(i + 1) % 3])) + 1];
  for (std::size_t v = 0; v + 1 < m_First.size(); ++v)
    m_First[v + 1] += m_First[v];
  m_Uses.resize(m_First.back());
  std::vector<std::size_t> next(m_First.begin(), m_First.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
    {
      const std::int32_t p = t[i], q = t[(i + 1) % 3];
      m_Uses[next[static_cast<std::size_t>(std::min(p, q))]++] = { std::max(p, q), static_cast<std::uint32_t>(f), p < q };
    }
  }
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

#include "Measures/VertexFans.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

FanCounts& FanCounts::operator+=(const FanCounts& other)
{
  edges += other.edges;
  edgeUses += other.edgeUses;
  folded += other.folded;
  inconsistent += other.inconsistent;
  boundary += other.boundary;
  nonManifold += other.nonManifold;
  nonManifoldVertices += other.nonManifoldVertices;
  return *this;
}

bool foldedNormals(const std::array<float, 3>& m, const std::array<float, 3>& n)
{
  static const double foldCosine = std::cos(M_PI / 180.0);
  return static_cast<double>(m[0]) * n[0] + static_cast<double>(m[1]) * n[1] + static_cast<double>(m[2]) * n[2] <
         -foldCosine;
}

std::size_t VertexFanTally::fans(const VertexCorner* first, const VertexCorner* last)
{
  // The link's edges (next, previous of each corner) joined in a small union-find over its vertices.
  m_Link.clear();
  m_Parent.clear();
  auto index = [&](std::int32_t vertex)
  {
    const auto at = std::find(m_Link.begin(), m_Link.end(), vertex);
    if (at != m_Link.end())
      return static_cast<std::size_t>(at - m_Link.begin());
    m_Link.push_back(vertex);
    m_Parent.push_back(m_Parent.size());
    return m_Link.size() - 1;
  };
  auto root = [&](std::size_t x)
  {
    while (m_Parent[x] != x)
      x = m_Parent[x] = m_Parent[m_Parent[x]];
    return x;
  };
  for (const VertexCorner* corner = first; corner != last; ++corner)
  {
    const std::size_t a = root(index(corner->next)), b = root(index(corner->previous));
    if (a != b)
      m_Parent[std::max(a, b)] = std::min(a, b);
  }
  std::size_t fans = 0;
  for (std::size_t i = 0; i < m_Link.size(); ++i)
    fans += root(i) == i;
  return fans;
}

} // namespace slicemesh

// Union-find over the integers 0..n-1 (path halving; the smaller index is the root, so the result
// does not depend on the order of the unions).
#ifndef DisjointSets_h
#define DisjointSets_h

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace slicemesh
{

class DisjointSets
{
public:
  explicit DisjointSets(std::size_t n)
    : m_Parent(n)
  {
    std::iota(m_Parent.begin(), m_Parent.end(), 0);
  }
  std::size_t find(std::size_t i)
  {
    while (m_Parent[i] != i)
      i = m_Parent[i] = m_Parent[m_Parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if (a != b)
      m_Parent[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<std::size_t> m_Parent;
};

} // namespace slicemesh

#endif

#include "PhantomCombinators.h"

#include <algorithm>
#include <stdexcept>

namespace slicemesh
{

DisjointUnion::DisjointUnion(PhantomPointer first, PhantomPointer second)
  : m_First(std::move(first))
  , m_Second(std::move(second))
{
  if (!m_First || !m_Second)
    throw std::invalid_argument("DisjointUnion: needs two shapes");
}

double DisjointUnion::signedDistance(const Vector3& point) const
{
  return std::min(m_First->signedDistance(point), m_Second->signedDistance(point));
}

double DisjointUnion::volume() const
{
  return m_First->volume() + m_Second->volume();
}

Bounds DisjointUnion::bounds() const
{
  const Bounds a = m_First->bounds();
  const Bounds b = m_Second->bounds();
  return { a.lower.cwiseMin(b.lower), a.upper.cwiseMax(b.upper) };
}

NestedSubtraction::NestedSubtraction(PhantomPointer outer, PhantomPointer inner)
  : m_Outer(std::move(outer))
  , m_Inner(std::move(inner))
{
  if (!m_Outer || !m_Inner)
    throw std::invalid_argument("NestedSubtraction: needs two shapes");
}

double NestedSubtraction::signedDistance(const Vector3& point) const
{
  return std::max(m_Outer->signedDistance(point), -m_Inner->signedDistance(point));
}

double NestedSubtraction::volume() const
{
  return m_Outer->volume() - m_Inner->volume();
}

Bounds NestedSubtraction::bounds() const
{
  return m_Outer->bounds();
}

} // namespace slicemesh

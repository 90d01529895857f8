// Compositions of phantoms for topology tests: several components, cavities.
// Each keeps the distance function exact only under a stated precondition, which the caller
// must respect (it is not checked): min/max of distances is exact for disjoint or nested
// shapes, but only a bound for overlapping ones.
#ifndef PhantomCombinators_h
#define PhantomCombinators_h

#include "Phantom.h"

namespace slicemesh
{

/** Two shapes that do not overlap (touching is fine): two components, or two touching
 *  structures. Distance min(a, b); volume a + b. */
class DisjointUnion : public Phantom
{
public:
  DisjointUnion(PhantomPointer first, PhantomPointer second);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  PhantomPointer m_First;
  PhantomPointer m_Second;
};

/** A shape with a cavity: inner lies strictly inside outer. Distance max(outer, -inner);
 *  volume outer - inner. */
class NestedSubtraction : public Phantom
{
public:
  NestedSubtraction(PhantomPointer outer, PhantomPointer inner);
  double signedDistance(const Vector3& point) const override;
  double volume() const override;
  Bounds bounds() const override;

private:
  PhantomPointer m_Outer;
  PhantomPointer m_Inner;
};

} // namespace slicemesh

#endif

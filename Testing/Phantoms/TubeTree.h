// Tubes of one radius around a set of line segments (a capsule for one segment; a pants / Y shape or
// a many-branch junction for segments sharing an end point): the points within radius of the skeleton.
// Signed distance: distance to the nearest segment minus the radius. It is exact everywhere outside
// and inside every single capsule; where two tubes meet (the crease of a branching) it is exact
// outside and, inside, a lower bound on the depth (the boundary there is farther than the nearer
// tube wall). Rasterizing needs only its sign, which is exact.
// Volume: closed form for one segment; for several, by numerical integration at construction
// (midpoint rule on a grid of radius/24, accurate to about 0.1%): a union of capsules has no closed form.
#ifndef TubeTree_h
#define TubeTree_h

#include "Phantom.h"

#include <utility>
#include <vector>

namespace slicemesh
{

class TubeTree : public Phantom
{
public:
  using Segment = std::pair<Vector3, Vector3>;
  TubeTree(std::vector<Segment> segments, double radius);
  double signedDistance(const Vector3& point) const override;
  double volume() const override { return m_Volume; }
  Bounds bounds() const override;

private:
  std::vector<Segment> m_Segments;
  double m_Radius;
  double m_Volume = 0.0;
};

/** The distance from point to the segment [a, b]. */
double distanceToSegment(const Vector3& point, const Vector3& a, const Vector3& b);

} // namespace slicemesh

#endif

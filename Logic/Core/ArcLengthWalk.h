// The one walk along a closed contour by arc length, for the stages that place points evenly along
// contours (the resampling of contours, the implicit function's samples on them).
#ifndef ArcLengthWalk_h
#define ArcLengthWalk_h

#include "Core/PlanarGeometry.h"

#include <algorithm>

namespace slicemesh
{

/** The length of `edges` edges of the closed contour, from its point `from` on (round past its last
 *  point): the edges' lengths summed in order, as ArcLengthWalk sums them. */
inline double arcLength(const Polygon2& contour, std::size_t from, std::size_t edges)
{
  const std::size_t n = contour.size();
  double length = 0.0;
  for (std::size_t i = 0; i < edges; ++i)
    length += distance(contour[(from + i) % n], contour[(from + i + 1) % n]);
  return length;
}

/** A walk along a closed contour of at least two points, asked for arc lengths in increasing order:
 *  each is found from the edge the one before was on, so m arc lengths along n edges cost n + m. */
class ArcLengthWalk
{
public:
  /** Round the whole contour from its first point. */
  explicit ArcLengthWalk(const Polygon2& contour)
    : ArcLengthWalk(contour, 0, contour.size())
  {
  }
  /** Over `edges` (at least one) of its edges from its point `from` on, round past its last point. */
  ArcLengthWalk(const Polygon2& contour, std::size_t from, std::size_t edges)
    : m_Contour(contour)
    , m_From(from)
    , m_Edges(edges)
    , m_Length(distance(corner(0), corner(1)))
  {
  }

  /** Moves on to the first edge that ends at arc length s or beyond; false when none does (s lies
   *  past the walk's end, and the walk stays on its last edge). */
  bool reach(double s)
  {
    while (m_Start + m_Length < s && m_Edge + 1 < m_Edges)
    {
      m_Start += m_Length;
      ++m_Edge;
      m_Length = distance(corner(m_Edge), corner(m_Edge + 1));
    }
    return m_Start + m_Length >= s;
  }

  /** The point at arc length s on the line of the current edge (its start, on an edge of no length). */
  Point2 at(double s) const { return along(fraction(s)); }

  /** at(s) held to the current edge: an arc length past the walk's end by rounding gives its end. */
  Point2 onEdgeAt(double s) const { return along(std::clamp(fraction(s), 0.0, 1.0)); }

private:
  const Point2& corner(std::size_t k) const { return m_Contour[(m_From + k) % m_Contour.size()]; }
  double fraction(double s) const { return m_Length > 0.0 ? (s - m_Start) / m_Length : 0.0; }
  Point2 along(double t) const
  {
    const Point2& a = corner(m_Edge);
    const Point2& b = corner(m_Edge + 1);
    return { a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
  }

  const Polygon2& m_Contour;
  std::size_t m_From;
  std::size_t m_Edges;
  std::size_t m_Edge = 0; ///< the current edge: corner(m_Edge) -> corner(m_Edge + 1)
  double m_Start = 0.0;   ///< the arc length at its start
  double m_Length;        ///< its length
};

} // namespace slicemesh

#endif

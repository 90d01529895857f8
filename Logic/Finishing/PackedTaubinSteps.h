// The Taubin pairs' steps on a working copy of the points packed for speed: single precision, four
// floats a point, and every vertex's neighbours in eight slots. The pairs are most of the smoothing's
// time, and a step's time is its instructions and its branches, not memory: in double precision with
// a loop over each vertex's five to seven neighbours, the loop's end was mispredicted at about every
// vertex. Internal to the finishing (SurfaceSmoothing).
#ifndef PackedTaubinSteps_h
#define PackedTaubinSteps_h

#include "Core/SliceMeshTypes.h"
#include "Finishing/EllipsoidClamp.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace slicemesh
{

/** Four floats in one 16-byte register (GCC's and Clang's vector extension): x, y, z and a zero. */
using Float4 = float __attribute__((vector_size(16)));

/** Points in single precision, relative to the middle of their box (the rounding, under 0.1 um a
 *  coordinate for a surface a metre across, is far below what the filter moves), and one more point
 *  at the origin that stays there: NeighbourSlots' empty slots name it. */
class PackedPoints
{
public:
  explicit PackedPoints(const std::vector<Point3>& points);

  Float4 pack(const Point3& p) const;
  Point3 unpack(std::size_t v) const;
  /** points[v] = unpack(v) for every point but the extra one. */
  void unpackInto(std::vector<Point3>& points) const;

  std::vector<Float4>& data() { return packed; }
  const std::vector<Float4>& data() const { return packed; }

private:
  Point3 origin;
  std::vector<Float4> packed;
};

/** The neighbours of every vertex in slots of eight: a vertex with fewer has the rest name the extra
 *  point at the origin (`zero`), one with more has the others in `more`, and an isolated vertex names
 *  itself eight times. Every vertex then sums eight points, with no branch on how many it has. */
struct NeighbourSlots
{
  static constexpr std::size_t slots = 8;
  /** From compressed rows: the neighbours of v are ids[first[v]] .. ids[first[v + 1]] - 1. The
   *  vertices side by side on `threads` threads (the same slots for any number). */
  NeighbourSlots(const std::vector<std::size_t>& first, const std::vector<std::int32_t>& ids,
                 unsigned int threads = 1);
  /** The compressed rows they were made from, read back (the same neighbours in the same order), for
   *  rows that name no vertex twice (as neighbour rows do: a vertex is at most once its own). */
  void rowsInto(std::vector<std::size_t>& first, std::vector<std::int32_t>& ids, unsigned int threads = 1) const;

  std::vector<std::int32_t> ids;   ///< vertex v's slots are ids[slots * v] .. ids[slots * v + slots - 1]
  std::vector<float> inverseCount; ///< 1 / the number of neighbours (1 / slots when isolated)
  std::vector<std::int32_t> more;  ///< the neighbours past the eighth, by vertex
  std::vector<std::size_t> moreOf; ///< vertex v's are more[moreOf[v]] .. more[moreOf[v + 1] - 1]
  std::size_t zero = 0;            ///< the extra point's index: the number of vertices
};

/** Where a packed point may go: within the ellipsoid of semi-axes `bound` around its start
 *  (inactive: anywhere); once `holdFeatures` is called, the points not flagged `held` within the
 *  ellipsoid of semi-axes `wide`. The smoothing's bound, on packed points. */
class PackedBound
{
public:
  PackedBound(const std::vector<Float4>& start, const std::array<double, 3>& bound, bool active);

  void holdFeatures(const std::vector<char>& held, const std::array<double, 3>& wide);

  /** p, or if it has left its ellipsoid, the ellipsoid's point nearest to it. */
  Float4 clamped(const Float4& p, std::size_t v) const
  {
    if (!active)
      return p;
    const Float4 d = p - start[v];
    const Float4 axes = held && !(*held)[v] ? wideInverse : inverse;
    const Float4 u = d * axes;
    const float reachSquared = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    if (reachSquared <= 1.0f)
      return p;
    const Float4 w = axes * axes;
    const std::array<float, 3> f = nearestOnEllipsoidFactors<float>({ u[0], u[1], u[2] }, { w[0], w[1], w[2] });
    return start[v] + d * Float4{ f[0], f[1], f[2], 0.0f };
  }

private:
  const std::vector<Float4>& start;
  bool active;
  Float4 inverse;
  Float4 wideInverse;
  const std::vector<char>* held = nullptr;
};

/** p += factor * (mean of the neighbours - p), for every vertex at once, each result clamped by
 *  `bound`; `scratch` (as large as `points`) receives the new points and is swapped in. */
void packedUmbrellaStep(std::vector<Float4>& points, const NeighbourSlots& neighbours, float factor,
                        std::vector<Float4>& scratch, const PackedBound& bound, unsigned int threads);

/** Taubin's lambda/mu pairs on a packed copy of `start`: each pair a free shrinking step and an
 *  inflating step within the bound, then the held vertices put back. */
class TaubinPairs
{
public:
  /** `neighbours`: the vertices' neighbours, held by reference (the caller keeps them, and may drop
   *  its other copies of them meanwhile); `bound`, `bounded`: the smoothing's displacement bound;
   *  `held`: vertices put back where they started after every pair. */
  TaubinPairs(const std::vector<Point3>& start, const NeighbourSlots& neighbours, const std::array<double, 3>& bound,
              bool bounded, std::vector<std::size_t> held);
  TaubinPairs(const std::vector<Point3>& start, NeighbourSlots&& neighbours, const std::array<double, 3>& bound,
              bool bounded, std::vector<std::size_t> held) = delete; // would outlive them
  // Its bounds refer to its own start points: not to be copied.
  TaubinPairs(const TaubinPairs&) = delete;
  TaubinPairs& operator=(const TaubinPairs&) = delete;

  /** Up to `pairs` pairs, fewer when a pair leaves the points as they were (checked every
   *  fixedPointCheck pairs: the rest would too); returns how many ran. */
  int run(int pairs, double lambda, double mu, unsigned int threads);
  static constexpr int fixedPointCheck = 4;
  /** From now on the `features` (a flag per vertex) stay where they are, and the others move within
   *  the ellipsoid of semi-axes `wide`. */
  void holdFeatures(const std::vector<char>& features, const std::array<double, 3>& wide);
  /** The points as they are now. */
  void unpackInto(std::vector<Point3>& points) const { packed.unpackInto(points); }

private:
  PackedPoints packed;
  std::vector<Float4> start;
  std::vector<Float4> scratch;
  const NeighbourSlots& neighbours;
  PackedBound free;
  PackedBound bound;
  std::vector<std::size_t> held;
  std::vector<std::size_t> features;
  std::vector<Float4> featuresAt;
};

} // namespace slicemesh

#endif

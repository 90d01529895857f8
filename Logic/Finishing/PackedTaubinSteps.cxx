#include "Finishing/PackedTaubinSteps.h"

#include "Core/BoundingBox.h"
#include "Core/ParallelFor.h"

#include <algorithm>
#include <cstring>

namespace slicemesh
{
namespace
{

Point3 middleOf(const std::vector<Point3>& points)
{
  if (points.empty())
    return {};
  BoundingBox box;
  for (const Point3& p : points)
    box.add(p);
  return { 0.5 * (box.low[0] + box.high[0]), 0.5 * (box.low[1] + box.high[1]), 0.5 * (box.low[2] + box.high[2]) };
}

Float4 inverseOf(const std::array<double, 3>& axes)
{
  return Float4{ static_cast<float>(1.0 / axes[0]), static_cast<float>(1.0 / axes[1]),
                 static_cast<float>(1.0 / axes[2]), 0.0f };
}

} // namespace

PackedPoints::PackedPoints(const std::vector<Point3>& points)
  : origin(middleOf(points))
  , packed(points.size() + 1, Float4{ 0.0f, 0.0f, 0.0f, 0.0f })
{
  for (std::size_t v = 0; v < points.size(); ++v)
    packed[v] = pack(points[v]);
}

Float4 PackedPoints::pack(const Point3& p) const
{
  return Float4{ static_cast<float>(p.x - origin.x), static_cast<float>(p.y - origin.y),
                 static_cast<float>(p.z - origin.z), 0.0f };
}

Point3 PackedPoints::unpack(std::size_t v) const
{
  const Float4& p = packed[v];
  return { origin.x + static_cast<double>(p[0]), origin.y + static_cast<double>(p[1]),
           origin.z + static_cast<double>(p[2]) };
}

void PackedPoints::unpackInto(std::vector<Point3>& points) const
{
  for (std::size_t v = 0; v + 1 < packed.size(); ++v)
    points[v] = unpack(v);
}

NeighbourSlots::NeighbourSlots(const std::vector<std::size_t>& first, const std::vector<std::int32_t>& neighbours,
                               unsigned int threads)
  : zero(first.size() - 1)
{
  // Where each vertex's neighbours past the eighth go, then every vertex's slots on its own.
  moreOf.assign(zero + 1, 0);
  for (std::size_t v = 0; v < zero; ++v)
    moreOf[v + 1] = moreOf[v] + (first[v + 1] - first[v] > slots ? first[v + 1] - first[v] - slots : 0);
  ids.resize(slots * zero);
  inverseCount.resize(zero);
  more.resize(moreOf[zero]);
  parallelForRanges(zero, threads,
                    [&](std::size_t firstVertex, std::size_t lastVertex)
                    {
                      for (std::size_t v = firstVertex; v < lastVertex; ++v)
                      {
                        const std::size_t begin = first[v], end = first[v + 1];
                        // Unused slots name the extra point (at the origin); an isolated vertex's, itself.
                        std::fill_n(ids.begin() + static_cast<std::ptrdiff_t>(slots * v), slots,
                                    static_cast<std::int32_t>(begin == end ? v : zero));
                        for (std::size_t i = begin; i < end; ++i)
                          if (i - begin < slots)
                            ids[slots * v + (i - begin)] = neighbours[i];
                          else
                            more[moreOf[v] + (i - begin - slots)] = neighbours[i];
                        inverseCount[v] = 1.0f / static_cast<float>(begin == end ? slots : end - begin);
                      }
                    });
}

void NeighbourSlots::rowsInto(std::vector<std::size_t>& first, std::vector<std::int32_t>& rowIds,
                              unsigned int threads) const
{
  // A vertex's own neighbours fill its slots from the first; the rest name the extra point. An
  // isolated vertex names itself in every slot (a vertex is at most once its own neighbour).
  auto inSlots = [&](std::size_t v) -> std::size_t
  {
    const std::int32_t* own = ids.data() + slots * v;
    const auto self = static_cast<std::int32_t>(v);
    if (own[0] == self && own[1] == self)
      return 0;
    return static_cast<std::size_t>(std::find(own, own + slots, static_cast<std::int32_t>(zero)) - own);
  };
  first.assign(zero + 1, 0);
  for (std::size_t v = 0; v < zero; ++v)
    first[v + 1] = first[v] + inSlots(v) + (moreOf[v + 1] - moreOf[v]);
  rowIds.resize(first[zero]);
  parallelForRanges(zero, threads,
                    [&](std::size_t firstVertex, std::size_t lastVertex)
                    {
                      for (std::size_t v = firstVertex; v < lastVertex; ++v)
                      {
                        const auto to = rowIds.begin() + static_cast<std::ptrdiff_t>(first[v]);
                        const auto slotted = std::copy_n(ids.begin() + static_cast<std::ptrdiff_t>(slots * v), inSlots(v), to);
                        std::copy(more.begin() + static_cast<std::ptrdiff_t>(moreOf[v]),
                                  more.begin() + static_cast<std::ptrdiff_t>(moreOf[v + 1]), slotted);
                      }
                    });
}

PackedBound::PackedBound(const std::vector<Float4>& start, const std::array<double, 3>& bound, bool active)
  : start(start)
  , active(active)
  , inverse(inverseOf(bound))
  , wideInverse(inverse)
{
}

void PackedBound::holdFeatures(const std::vector<char>& held, const std::array<double, 3>& wide)
{
  this->held = &held;
  wideInverse = inverseOf(wide);
}

void packedUmbrellaStep(std::vector<Float4>& points, const NeighbourSlots& neighbours, float factor,
                        std::vector<Float4>& scratch, const PackedBound& bound, unsigned int threads)
{
  parallelForRanges(neighbours.zero, threads,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        const std::int32_t* slot = &neighbours.ids[NeighbourSlots::slots * v];
                        auto at = [&](int k) -> const Float4& { return points[static_cast<std::size_t>(slot[k])]; };
                        // Four sums side by side, not one chain of eight adds.
                        Float4 sum = ((at(0) + at(1)) + (at(2) + at(3))) + ((at(4) + at(5)) + (at(6) + at(7)));
                        for (std::size_t i = neighbours.moreOf[v]; i < neighbours.moreOf[v + 1]; ++i)
                          sum += points[static_cast<std::size_t>(neighbours.more[i])];
                        const Float4 p = points[v];
                        scratch[v] = bound.clamped(p + factor * (sum * neighbours.inverseCount[v] - p), v);
                      }
                    });
  points.swap(scratch);
}

TaubinPairs::TaubinPairs(const std::vector<Point3>& startPoints, const NeighbourSlots& slots,
                         const std::array<double, 3>& displacementBound, bool bounded,
                         std::vector<std::size_t> heldVertices)
  : packed(startPoints)
  , start(packed.data())
  , scratch(packed.data())
  , neighbours(slots)
  , free(start, {}, false)
  , bound(start, displacementBound, bounded)
  , held(std::move(heldVertices))
{
}

int TaubinPairs::run(int pairs, double lambda, double mu, unsigned int threads)
{
  std::vector<Float4> before;
  int i = 0;
  for (; i < pairs; ++i)
  {
    const bool check = i % fixedPointCheck == fixedPointCheck - 1;
    if (check)
      before = packed.data();
    packedUmbrellaStep(packed.data(), neighbours, static_cast<float>(lambda), scratch, free, threads);
    packedUmbrellaStep(packed.data(), neighbours, static_cast<float>(mu), scratch, bound, threads);
    for (std::size_t k = 0; k < features.size(); ++k)
      packed.data()[features[k]] = featuresAt[k];
    for (std::size_t v : held)
      packed.data()[v] = start[v];
    // A pair is a function of the points alone: once one leaves them as they were, bit for bit,
    // every later pair would too. A speck pressed against its bound gets there in a few pairs.
    if (check && std::memcmp(before.data(), packed.data().data(), before.size() * sizeof(Float4)) == 0)
      return i + 1;
  }
  return i;
}

void TaubinPairs::holdFeatures(const std::vector<char>& flags, const std::array<double, 3>& wide)
{
  features.clear();
  featuresAt.clear();
  for (std::size_t v = 0; v < flags.size(); ++v)
    if (flags[v])
    {
      features.push_back(v);
      featuresAt.push_back(packed.data()[v]);
    }
  bound.holdFeatures(flags, wide);
}

} // namespace slicemesh

#include "IntermediateSections.h"

#include "ContourCorrespondence.h"
#include "DisjointSets.h"
#include "MarchingSquares.h"
#include "PlanarGeometry.h"
#include "PolygonProximity.h"
#include "VariationalImplicit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

namespace slicemesh
{

namespace
{

using Clock = std::chrono::steady_clock;
using Layer = std::vector<Polygon2>;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double medianEdgeLength(const ContourStack& stack)
{
  std::vector<double> lengths;
  for (const Slice& slice : stack.slices)
    appendEdgeLengths(slice.contours, lengths);
  return median(std::move(lengths), 0.0);
}

Box2 unionBox(const Layer& a, const Layer& b)
{
  Box2 box{ HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Layer* layer : { &a, &b })
    for (const Polygon2& polygon : *layer)
    {
      if (polygon.empty())
        continue;
      const Box2 own = boundingBox(polygon);
      box = { std::min(box.xmin, own.xmin), std::min(box.ymin, own.ymin), std::max(box.xmax, own.xmax),
              std::max(box.ymax, own.ymax) };
    }
  return box;
}

/** Whether the sections between lower and upper join, by overlap from layer to layer, exactly the
 *  contours that the correspondence rule (at threshold) groups together: no group split, no two
 *  groups merged, no section contour unconnected to an original contour, and one contour per
 *  section along every one-to-one pair. */
bool sectionsKeepTopology(const Layer& lower, const std::vector<Layer>& sections, const Layer& upper, double threshold)
{
  std::vector<const Layer*> layers{ &lower };
  for (const Layer& s : sections)
    layers.push_back(&s);
  layers.push_back(&upper);
  std::vector<std::size_t> offset{ 0 };
  for (const Layer* layer : layers)
    offset.push_back(offset.back() + layer->size());
  DisjointSets chain(offset.back());
  for (std::size_t l = 0; l + 1 < layers.size(); ++l)
    for (const CorrespondenceGroup& group : matchContours(*layers[l], *layers[l + 1], 0.0).groups)
      for (const ContourLink& link : group.links)
        chain.unite(offset[l] + link.lower, offset[l + 1] + link.upper);

  const SlabCorrespondence original = matchContours(lower, upper, threshold);
  const std::size_t upperOffset = offset[layers.size() - 1];
  std::map<std::size_t, std::size_t> groupOfRoot; // chain component -> original group
  for (std::size_t g = 0; g < original.groups.size(); ++g)
  {
    const CorrespondenceGroup& group = original.groups[g];
    std::vector<std::size_t> members;
    for (std::size_t i : group.lower)
      members.push_back(chain.find(i));
    for (std::size_t j : group.upper)
      members.push_back(chain.find(upperOffset + j));
    for (std::size_t root : members)
    {
      if (root != members.front())
        return false; // the sections split a group
      const auto [it, inserted] = groupOfRoot.emplace(root, g);
      if (!inserted && it->second != g)
        return false; // the sections merge two groups
    }
    if (group.shape() == GroupShape::OneToOne)
      for (std::size_t l = 1; l + 1 < layers.size(); ++l)
      {
        std::size_t count = 0;
        for (std::size_t c = 0; c < layers[l]->size(); ++c)
          count += chain.find(offset[l] + c) == members.front() ? 1 : 0;
        if (count != 1)
          return false; // a one-to-one pair split or lost in a section
      }
  }
  for (std::size_t k = offset[1]; k < upperOffset; ++k)
    if (groupOfRoot.count(chain.find(k)) == 0)
      return false; // a section contour that belongs to nothing: an added component
  return true;
}

void checkOptions(const UndersamplingOptions& options)
{
  if (!(options.correspondenceDistance >= 0.0) || !std::isfinite(options.correspondenceDistance))
    throw Error("intermediate sections: correspondenceDistance must be finite and not negative");
  if (!(options.maxSliceSpacingFactor >= 0.0) || !std::isfinite(options.maxSliceSpacingFactor))
    throw Error("intermediate sections: maxSliceSpacingFactor must be finite and not negative");
  if (options.sampling.maxCentres < 12)
    throw Error("intermediate sections: the centre budget must allow at least 12 centres");
}

/** Area-weighted centroid of the regions of some contours. */
Point2 centroid(const std::vector<const Polygon2*>& contours)
{
  double area = 0.0, cx = 0.0, cy = 0.0;
  for (const Polygon2* polygon : contours)
  {
    const std::size_t n = polygon->size();
    double a = 0.0, x = 0.0, y = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Point2& p = (*polygon)[i];
      const Point2& q = (*polygon)[(i + 1) % n];
      const double cross = p.x * q.y - q.x * p.y;
      a += cross;
      x += (p.x + q.x) * cross;
      y += (p.y + q.y) * cross;
    }
    if (a == 0.0)
      continue;
    // Each region counts by its own (positive) area whatever the orientation.
    area += std::abs(a);
    cx += x / (3.0 * a) * std::abs(a);
    cy += y / (3.0 * a) * std::abs(a);
  }
  return area > 0.0 ? Point2{ cx / area, cy / area } : Point2{};
}

Polygon2 translated(const Polygon2& polygon, double dx, double dy)
{
  Polygon2 moved(polygon);
  for (Point2& p : moved)
  {
    p.x += dx;
    p.y += dy;
  }
  return moved;
}

/** An implicit function fitted in a sheared frame: the point (x, y) at height z is moved by
 *  -s(z) * shift, s(z) = (z - z0) / dz, so a group whose contours drift by `shift` from one slice to
 *  the next stands upright and overlaps itself in that frame (a straight prism for a shifted circle).
 *  shift = 0 gives the plain fit. */
struct ShearedFit
{
  VariationalImplicitFunction f;
  Point2 shift;
  Box2 box;           ///< the grid's box in the sheared frame
  bool holes = false; ///< the fit is of holes alone (solid = inside them): sections are reversed
};

/** Fits support slices (contours in the stack frame) in the frame sheared by shift over [z0, z0 + dz];
 *  the grid box covers the sheared contours of the slab's two slices (lower and upper) plus a margin. */
ShearedFit fitSheared(const std::vector<Slice>& support, const Layer& lower, const Layer& upper, double z0, double dz,
                      Point2 shift, bool holes, const ConstraintSampling& sampling)
{
  ShearedFit fit;
  fit.shift = shift;
  fit.holes = holes;
  std::vector<Slice> sheared;
  for (const Slice& slice : support)
  {
    const double s = (slice.z - z0) / dz;
    Slice moved{ slice.z, {} };
    for (const Polygon2& c : slice.contours)
      moved.contours.push_back(translated(c, -s * shift.x, -s * shift.y));
    sheared.push_back(std::move(moved));
  }
  fit.f.fit(contourConstraints(sheared, sampling));
  Layer upperSheared;
  for (const Polygon2& c : upper)
    upperSheared.push_back(translated(c, -shift.x, -shift.y));
  fit.box = unionBox(lower, upperSheared);
  return fit;
}

/** The zero level sets of all fits at height z, back in the stack frame. */
Layer sectionAt(const std::vector<ShearedFit>& fits, double z, double s, double h)
{
  Layer layer;
  for (const ShearedFit& fit : fits)
  {
    // Cells about the in-plane spacing (at most 256 a side), a margin so the contours close.
    const double extent = std::max(fit.box.xmax - fit.box.xmin, fit.box.ymax - fit.box.ymin);
    const double cell = std::max(h, extent / 255.0);
    const double margin = std::max(3.0 * cell, 0.1 * extent);
    const Box2 box{ fit.box.xmin - margin, fit.box.ymin - margin, fit.box.xmax + margin, fit.box.ymax + margin };
    const ScalarGrid2 grid =
      sampleGrid(box, cell, [&](const std::vector<Point2>& p, std::vector<double>& v) { fit.f.evaluatePlane(p, z, v); });
    for (Polygon2& loop : zeroContours(grid, 0.25 * cell * cell))
    {
      if (fit.holes)
        std::reverse(loop.begin(), loop.end());
      layer.push_back(translated(loop, s * fit.shift.x, s * fit.shift.y));
    }
  }
  return layer;
}

/** Whether the contours of one section neither cross nor touch (sections from separate fits could). */
bool contoursApart(const Layer& layer)
{
  std::vector<IndexedPolygon> indexed(layer.begin(), layer.end());
  for (std::size_t i = 0; i < indexed.size(); ++i)
    for (std::size_t j = i + 1; j < indexed.size(); ++j)
      if (boundaryDistance(indexed[i], indexed[j], 0.0) <= 0.0)
        return false;
  return true;
}

/** Contours of `beyond` (the slice next to the slab on one side) that correspond to the given
 *  members of `inside` (the slab's slice on that side), by the same rule. */
Layer partnersBeyond(const Layer& beyond, const Layer& inside, const std::vector<std::size_t>& members, double threshold)
{
  Layer partners;
  for (const CorrespondenceGroup& group : matchContours(beyond, inside, threshold).groups)
  {
    const bool ours = std::any_of(group.upper.begin(), group.upper.end(), [&](std::size_t j) {
      return std::find(members.begin(), members.end(), j) != members.end();
    });
    if (ours)
      for (std::size_t i : group.lower)
        partners.push_back(beyond[i]);
  }
  return partners;
}

} // namespace

ContourStack insertIntermediateSections(const ContourStack& stack, const UndersamplingOptions& options,
                                        SectionStatistics* statisticsOut)
{
  checkOptions(options);
  SectionStatistics statistics;
  const double h = medianEdgeLength(stack);
  statistics.inPlaneSpacing = h;
  const std::size_t n = stack.slices.size();
  const std::size_t cap = std::max<std::size_t>(options.maxSectionsPerSlab, 1);
  const double threshold = options.bridgeNonOverlapping ? options.correspondenceDistance : 0.0;
  auto slabName = [&](std::size_t k) {
    std::ostringstream name;
    name << "slab " << k << " (z " << stack.slices[k].z << " to " << stack.slices[k + 1].z << ")";
    return name.str();
  };

  ContourStack result;
  result.sliceSpacing = stack.sliceSpacing;
  for (std::size_t k = 0; k < n; ++k)
  {
    result.slices.push_back(stack.slices[k]);
    if (k + 1 >= n)
      break;
    const Slice& lowerSlice = stack.slices[k];
    const Slice& upperSlice = stack.slices[k + 1];
    const Layer& lower = lowerSlice.contours;
    const Layer& upper = upperSlice.contours;
    ++statistics.slabs;
    if (lower.empty() || upper.empty() || !(h > 0.0))
      continue; // nothing to interpolate between: caps close such slabs

    const double dz = upperSlice.z - lowerSlice.z;
    std::size_t spacingSections = 0;
    if (options.maxSliceSpacingFactor > 0.0 && dz > options.maxSliceSpacingFactor * h)
      spacingSections = std::min(cap, static_cast<std::size_t>(std::ceil(dz / (options.maxSliceSpacingFactor * h))) - 1);
    SlabCorrespondence correspondence;
    bool needBridge = false;
    if (options.bridgeNonOverlapping && threshold > 0.0)
    {
      correspondence = matchContours(lower, upper, threshold);
      for (const CorrespondenceGroup& group : correspondence.groups)
        needBridge = needBridge || group.hasDistanceOnlyLink();
    }
    if (spacingSections == 0 && !needBridge)
      continue;

    const Layer noContours;
    const Layer& below = k > 0 ? stack.slices[k - 1].contours : noContours;
    const Layer& above = k + 2 < n ? stack.slices[k + 2].contours : noContours;
    auto sectionsFor = [&](const std::vector<ShearedFit>& fits, std::size_t m) {
      std::vector<Layer> sections;
      for (std::size_t i = 1; i <= m; ++i)
      {
        const double s = static_cast<double>(i) / static_cast<double>(m + 1);
        sections.push_back(sectionAt(fits, lowerSlice.z + s * dz, s, h));
      }
      return sections;
    };
    auto fitOrNote = [&](auto&& makeFits, std::vector<ShearedFit>& fits) {
      const Clock::time_point start = Clock::now();
      try
      {
        makeFits(fits);
      }
      catch (const Error& e)
      {
        statistics.notes.push_back(slabName(k) + ": no implicit function (" + e.what() + ")");
        fits.clear();
      }
      statistics.fitSeconds += secondsSince(start);
      for (const ShearedFit& fit : fits)
        statistics.largestFit = std::max(statistics.largestFit, fit.f.centres());
      if (!fits.empty())
        ++statistics.slabsFitted;
      return !fits.empty();
    };

    std::vector<Layer> accepted;
    bool found = false;
    if (needBridge)
    {
      // One fit per group, each in the frame that follows the group's drift from slice to slice, so
      // a pair that corresponds only by distance overlaps itself there (paper 4.4: the implicit
      // function carries the shape across). Contours with no partner end here and get no sections.
      std::vector<ShearedFit> fits;
      const bool fitted = fitOrNote(
        [&](std::vector<ShearedFit>& out) {
          for (const CorrespondenceGroup& group : correspondence.groups)
          {
            if (group.lower.empty() || group.upper.empty())
              continue;
            std::vector<const Polygon2*> lowerMembers, upperMembers;
            Layer lowerGroup, upperGroup;
            for (std::size_t i : group.lower)
            {
              lowerMembers.push_back(&lower[i]);
              lowerGroup.push_back(lower[i]);
            }
            for (std::size_t j : group.upper)
            {
              upperMembers.push_back(&upper[j]);
              upperGroup.push_back(upper[j]);
            }
            const Point2 a = centroid(lowerMembers), b = centroid(upperMembers);
            std::vector<Slice> support;
            Layer belowPartners = partnersBeyond(below, lower, group.lower, threshold);
            if (!belowPartners.empty())
              support.push_back({ stack.slices[k - 1].z, std::move(belowPartners) });
            support.push_back({ lowerSlice.z, lowerGroup });
            support.push_back({ upperSlice.z, upperGroup });
            Layer abovePartners = partnersBeyond(above, upper, group.upper, threshold);
            if (!abovePartners.empty())
              support.push_back({ stack.slices[k + 2].z, std::move(abovePartners) });
            out.push_back(fitSheared(support, lowerGroup, upperGroup, lowerSlice.z, dz, { b.x - a.x, b.y - a.y },
                                     group.holes, options.sampling));
          }
        },
        fits);
      const Clock::time_point start = Clock::now();
      // More sections until consecutive layers overlap along every distance-matched pair.
      std::vector<std::size_t> counts;
      for (std::size_t m : { 1, 2, 3, 4, 6, 8, 12, 16, 24, 32 })
        if (m >= spacingSections && m < cap)
          counts.push_back(m);
      counts.push_back(cap);
      for (std::size_t m : counts)
      {
        if (!fitted || found)
          break;
        std::vector<Layer> sections = sectionsFor(fits, m);
        const bool apart = std::all_of(sections.begin(), sections.end(), contoursApart);
        if (apart && sectionsKeepTopology(lower, sections, upper, threshold))
        {
          accepted = std::move(sections);
          found = true;
        }
      }
      statistics.extractSeconds += secondsSince(start);
      if (found)
        ++statistics.slabsBridged;
      else
      {
        ++statistics.bridgesFailed;
        statistics.notes.push_back(slabName(k) + ": distance-matched contours not joined by up to " + std::to_string(cap) +
                                   " sections");
      }
    }
    if (!found && spacingSections > 0)
    {
      // One plain fit to all contours of the slab's slices and of the slices just beyond.
      std::vector<ShearedFit> fits;
      const bool fitted = fitOrNote(
        [&](std::vector<ShearedFit>& out) {
          std::vector<Slice> support;
          for (std::size_t s = (k > 0 ? k - 1 : 0); s <= std::min(k + 2, n - 1); ++s)
            if (!stack.slices[s].contours.empty())
              support.push_back(stack.slices[s]);
          out.push_back(fitSheared(support, lower, upper, lowerSlice.z, dz, {}, false, options.sampling));
        },
        fits);
      const Clock::time_point start = Clock::now();
      if (fitted)
      {
        std::vector<Layer> sections = sectionsFor(fits, spacingSections);
        if (sectionsKeepTopology(lower, sections, upper, 0.0))
        {
          accepted = std::move(sections);
          found = true;
        }
        else
        {
          ++statistics.slabsRejected;
          statistics.notes.push_back(slabName(k) + ": sections would change the topology; none inserted");
        }
      }
      statistics.extractSeconds += secondsSince(start);
    }
    if (!found)
      continue;
    ++statistics.slabsRefined;
    for (std::size_t i = 0; i < accepted.size(); ++i)
    {
      const double z = lowerSlice.z + dz * static_cast<double>(i + 1) / static_cast<double>(accepted.size() + 1);
      result.slices.push_back({ z, std::move(accepted[i]) });
      ++statistics.sectionsInserted;
    }
  }
  if (statisticsOut)
    *statisticsOut = statistics;
  return result;
}

} // namespace slicemesh

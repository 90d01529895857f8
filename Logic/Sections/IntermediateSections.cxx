#include "Sections/IntermediateSections.h"

#include "Correspondence/ContourCorrespondence.h"
#include "Contours/ContourResampling.h"
#include "Core/DisjointSets.h"
#include "Contours/MarchingSquares.h"
#include "Core/PlanarGeometry.h"
#include "Correspondence/PolygonProximity.h"
#include "Sections/VariationalImplicit.h"

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

/** The x-intervals in which the horizontal line y lies inside a layer's region (even-odd over all its
 *  contours, so holes are gaps), sorted. */
std::vector<std::pair<double, double>> spansAt(const Layer& layer, double y)
{
  std::vector<double> xs;
  for (const Polygon2& polygon : layer)
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % polygon.size()];
      if ((a.y <= y) != (b.y <= y))
        xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
  std::sort(xs.begin(), xs.end());
  std::vector<std::pair<double, double>> spans;
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2)
    spans.emplace_back(xs[i], xs[i + 1]);
  return spans;
}

/** Areas of the regions of a and b and of their intersection, by the midpoint rule over horizontal
 *  scanlines (exact along each line; 256 rows over the common height keep the error well under 1%
 *  for the smooth contours compared here). */
struct OverlapAreas
{
  double a = 0.0, b = 0.0, both = 0.0;
  /** The share of the smaller region that the other covers: 1 when one contains the other. */
  double fraction() const { return std::min(a, b) > 0.0 ? both / std::min(a, b) : 0.0; }
};

OverlapAreas overlapAreas(const Layer& a, const Layer& b)
{
  OverlapAreas areas;
  const Box2 box = unionBox(a, b);
  if (!(box.ymax > box.ymin))
    return areas;
  constexpr int rows = 256;
  const double dy = (box.ymax - box.ymin) / rows;
  for (int r = 0; r < rows; ++r)
  {
    const double y = box.ymin + (r + 0.5) * dy;
    const auto sa = spansAt(a, y), sb = spansAt(b, y);
    for (const auto& [x0, x1] : sa)
      areas.a += (x1 - x0) * dy;
    for (const auto& [x0, x1] : sb)
      areas.b += (x1 - x0) * dy;
    // Length of the intersection of two sorted interval lists.
    for (std::size_t i = 0, j = 0; i < sa.size() && j < sb.size();)
    {
      areas.both += std::max(0.0, std::min(sa[i].second, sb[j].second) - std::max(sa[i].first, sb[j].first)) * dy;
      (sa[i].second < sb[j].second ? i : j) += 1;
    }
  }
  return areas;
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
  if (!(options.sectionOverlap >= 0.0 && options.sectionOverlap < 1.0))
    throw Error("intermediate sections: sectionOverlap must be at least 0 and less than 1");
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

/** How far z is compressed in the frame of a fit over a slab dz thick whose contours are `thickness`
 *  wide (see ShearedFit). */
double zCompression(double thickness, double dz)
{
  // Thin-plate interpolation knows the shape only on the slices; across a slab thicker than the shape
  // is wide it bulges or pinches half way (measured on the 5 mm capsule, 2.6 mm thick: sections +9% in
  // area in an end slab, -4% in a middle one, +30% with the slab's two slices alone). With the slab
  // no thicker than half the shape's thickness in the fit's frame, sections stay within ~1-2% of the
  // blend of their neighbours.
  constexpr double slabPerThickness = 0.5;
  return thickness > 0.0 && dz > 0.0 ? std::min(1.0, slabPerThickness * thickness / dz) : 1.0;
}

/** 2 area / perimeter over some contours: how thick they are (a disc of radius r gives r, a long strip
 *  of width w about w). */
double meanThickness(const std::vector<const Layer*>& layers)
{
  double area = 0.0, length = 0.0;
  for (const Layer* layer : layers)
    for (const Polygon2& polygon : *layer)
    {
      area += std::abs(0.5 * twiceSignedArea(polygon));
      length += perimeter(polygon);
    }
  return length > 0.0 ? 2.0 * area / length : 0.0;
}

/** An implicit function fitted in a sheared, z-compressed frame: the point (x, y) at height z is
 *  moved by -s(z) * shift, s(z) = (z - z0) / dz, so a group whose contours drift by `shift` from one
 *  slice to the next stands upright and overlaps itself in that frame (a straight prism for a shifted
 *  circle); and z - z0 is multiplied by zScale <= 1 (zCompression). shift = 0 and zScale = 1 give the
 *  plain fit. */
struct ShearedFit
{
  VariationalImplicitFunction f;
  Point2 shift;
  double z0 = 0.0;
  double zScale = 1.0;
  Box2 box;           ///< the grid's box in the sheared frame
  bool holes = false; ///< the fit is of holes alone (solid = inside them): sections are reversed
  Layer lower, upper; ///< the fit's contours on the slab's two slices (stack frame)
};

/** Fits support slices (contours in the stack frame) in the frame sheared by shift over [z0, z0 + dz];
 *  the grid box covers the sheared contours of the slab's two slices (lower and upper) plus a margin. */
ShearedFit fitSheared(const std::vector<Slice>& support, const Layer& lower, const Layer& upper, double z0, double dz,
                      Point2 shift, bool holes, const ConstraintSampling& sampling)
{
  ShearedFit fit;
  fit.shift = shift;
  fit.holes = holes;
  fit.z0 = z0;
  fit.zScale = zCompression(meanThickness({ &lower, &upper }), dz);
  fit.lower = lower;
  fit.upper = upper;
  std::vector<Slice> sheared;
  for (const Slice& slice : support)
  {
    const double s = (slice.z - z0) / dz;
    Slice moved{ z0 + fit.zScale * (slice.z - z0), {} };
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

/** The zero level set of one fit at height z (fraction s of the slab), back in the stack frame. */
Layer sectionOf(const ShearedFit& fit, double z, double s, double h)
{
  Layer layer;
  // Cells about the in-plane spacing (at most 256 a side), a margin so the contours close.
  const double extent = std::max(fit.box.xmax - fit.box.xmin, fit.box.ymax - fit.box.ymin);
  const double cell = std::max(h, extent / 255.0);
  const double margin = std::max(3.0 * cell, 0.1 * extent);
  const Box2 box{ fit.box.xmin - margin, fit.box.ymin - margin, fit.box.xmax + margin, fit.box.ymax + margin };
  const double zFit = fit.z0 + fit.zScale * (z - fit.z0);
  const ScalarGrid2 grid =
    sampleGrid(box, cell, [&](const std::vector<Point2>& p, std::vector<double>& v) { fit.f.evaluatePlane(p, zFit, v); });
  for (Polygon2& loop : zeroContours(grid, 0.25 * cell * cell))
  {
    if (fit.holes)
      std::reverse(loop.begin(), loop.end());
    layer.push_back(translated(loop, s * fit.shift.x, s * fit.shift.y));
  }
  // Marching squares leaves edges from a hair to a cell long (a crossing next to a grid node):
  // resampled to the stack's point spacing, keeping the area, a section is sampled like the slices,
  // with half the triangles and none of the folded pairs that the hair-thin edges made (measured:
  // 18 folded edges on the 5 mm capsule and 3 on the 2 mm helix before, 0 after).
  return resampleContours(layer, h, ResampledShape::KeepingArea);
}

/** The smallest share of the smaller region by which corresponding regions (the unions of the
 *  contours of each group of the overlap rule) of consecutive layers overlap, from lower through the
 *  sections to upper. */
double smallestLayerOverlap(const Layer& lower, const std::vector<Layer>& sections, const Layer& upper)
{
  std::vector<const Layer*> layers{ &lower };
  for (const Layer& section : sections)
    layers.push_back(&section);
  layers.push_back(&upper);
  double smallest = 1.0;
  for (std::size_t l = 0; l + 1 < layers.size(); ++l)
    for (const CorrespondenceGroup& group : matchContours(*layers[l], *layers[l + 1], 0.0).groups)
    {
      if (group.lower.empty() || group.upper.empty())
        continue;
      Layer a, b;
      for (std::size_t i : group.lower)
        a.push_back((*layers[l])[i]);
      for (std::size_t j : group.upper)
        b.push_back((*layers[l + 1])[j]);
      smallest = std::min(smallest, overlapAreas(a, b).fraction());
    }
  return smallest;
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
  result.coordinateStep = stack.coordinateStep;
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
    bool needBridge = false, weakOverlap = false;
    if ((options.bridgeNonOverlapping && threshold > 0.0) || options.refineWeakOverlap)
    {
      correspondence = matchContours(lower, upper, threshold);
      for (const CorrespondenceGroup& group : correspondence.groups)
      {
        needBridge = needBridge || group.hasDistanceOnlyLink();
        if (options.refineWeakOverlap && !group.lower.empty() && !group.upper.empty())
        {
          Layer lowerGroup, upperGroup;
          for (std::size_t i : group.lower)
            lowerGroup.push_back(lower[i]);
          for (std::size_t j : group.upper)
            upperGroup.push_back(upper[j]);
          weakOverlap = weakOverlap || overlapAreas(lowerGroup, upperGroup).fraction() < options.sectionOverlap;
        }
      }
    }
    if (spacingSections == 0 && !needBridge && !weakOverlap)
      continue;

    const Layer noContours;
    const Layer& below = k > 0 ? stack.slices[k - 1].contours : noContours;
    const Layer& above = k + 2 < n ? stack.slices[k + 2].contours : noContours;
    // m evenly spaced sections, each the union of the fits' zero sets at its height.
    auto sectionsFor = [&](const std::vector<ShearedFit>& fits, std::size_t m) {
      std::vector<Layer> sections(m);
      for (std::size_t i = 0; i < m; ++i)
      {
        const double s = static_cast<double>(i + 1) / static_cast<double>(m + 1);
        for (const ShearedFit& fit : fits)
        {
          Layer part = sectionOf(fit, lowerSlice.z + s * dz, s, h);
          sections[i].insert(sections[i].end(), part.begin(), part.end());
        }
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
    double acceptedOverlap = 1.0;
    bool found = false;
    // Tries the counts in turn: keeps the last sections that keep the topology (and whose contours
    // stay apart), and stops at the first whose consecutive layers overlap by sectionOverlap (or at
    // once when the overlap does not matter).
    auto chooseSections = [&](const std::vector<ShearedFit>& fits, const std::vector<std::size_t>& counts,
                              double topologyThreshold, bool overlapMatters) {
      for (std::size_t m : counts)
      {
        std::vector<Layer> sections = sectionsFor(fits, m);
        const bool apart = std::all_of(sections.begin(), sections.end(), contoursApart);
        if (!apart || !sectionsKeepTopology(lower, sections, upper, topologyThreshold))
          continue;
        accepted = std::move(sections);
        found = true;
        if (!overlapMatters)
          break;
        acceptedOverlap = smallestLayerOverlap(lower, accepted, upper);
        if (acceptedOverlap >= options.sectionOverlap)
          return; // otherwise keep these and try more sections
      }
      if (found && overlapMatters)
      {
        std::ostringstream note;
        note << slabName(k) << ": consecutive sections overlap by " << acceptedOverlap << " only (" << accepted.size()
             << " sections, the most that keep the topology within the cap)";
        statistics.notes.push_back(note.str());
      }
    };
    // first, then the usual steps above it, then the cap.
    auto countsFrom = [&](std::size_t first) {
      std::vector<std::size_t> counts{ first };
      for (std::size_t m : { 2, 3, 4, 6, 8, 12, 16, 24, 32 })
        if (m > first && m < cap)
          counts.push_back(m);
      if (cap > first)
        counts.push_back(cap);
      return counts;
    };
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
      // More sections until consecutive layers overlap by options.sectionOverlap of the smaller region
      // (the paper asks only for some overlap, but the tiling of partly overlapping contours loses
      // volume: see UndersamplingOptions). The first count tried is the one at which the groups' own
      // contours, moved along their drift by one step, would overlap that much.
      auto predictedOverlap = [&](std::size_t m) {
        double smallest = 1.0;
        for (const ShearedFit& fit : fits)
        {
          const double fx = fit.shift.x / static_cast<double>(m + 1), fy = fit.shift.y / static_cast<double>(m + 1);
          for (const Layer* layer : { &fit.lower, &fit.upper })
          {
            Layer moved;
            for (const Polygon2& c : *layer)
              moved.push_back(translated(c, fx, fy));
            smallest = std::min(smallest, overlapAreas(*layer, moved).fraction());
          }
        }
        return smallest;
      };
      std::size_t first = std::max<std::size_t>(spacingSections, 1);
      while (fitted && first < cap && predictedOverlap(first) < options.sectionOverlap)
        ++first;
      if (fitted)
        chooseSections(fits, countsFrom(first), threshold, true);
      statistics.extractSeconds += secondsSince(start);
      if (found)
      {
        ++statistics.slabsBridged;
        statistics.smallestSectionOverlap = std::min(statistics.smallestSectionOverlap, acceptedOverlap);
      }
      else
      {
        ++statistics.bridgesFailed;
        statistics.notes.push_back(slabName(k) + ": distance-matched contours not joined by up to " + std::to_string(cap) +
                                   " sections");
      }
    }
    if (!found && (spacingSections > 0 || (weakOverlap && !needBridge)))
    {
      // One plain fit to all contours of the slab's slices and of the slices just beyond: the pairs
      // overlap already, so no shear is needed (and a drift that is a turn, as along a helix, has no
      // one shear that fits it).
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
      const bool overlapMatters = weakOverlap && !needBridge;
      if (fitted)
        chooseSections(fits, overlapMatters ? countsFrom(std::max<std::size_t>(spacingSections, 1))
                                            : std::vector<std::size_t>{ spacingSections },
                       0.0, overlapMatters);
      statistics.extractSeconds += secondsSince(start);
      if (found && overlapMatters)
      {
        ++statistics.slabsOverlapRefined;
        statistics.smallestSectionOverlap = std::min(statistics.smallestSectionOverlap, acceptedOverlap);
      }
      if (fitted && !found)
      {
        ++statistics.slabsRejected;
        statistics.notes.push_back(slabName(k) + ": sections would change the topology; none inserted");
      }
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

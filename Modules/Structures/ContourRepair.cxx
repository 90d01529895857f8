#include "ContourRepair.h"

#include "Contours/ContourCrossings.h"
#include "Core/PlanarGeometry.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slicemesh
{
namespace
{

// Clipper works on integers: 0.1 micrometre steps.
constexpr double Scale = 1e4;
// Where pieces meet at a point they are pulled apart by this much (mm).
constexpr double Separation = 1.5e-3;

// Farthest a contour point may lie from the origin (mm): Clipper holds integers up to 4.6e18,
// and the points are scaled by Scale. A kilometre's worth of margin over any anatomy in a file.
constexpr double Reach = 1e6;

/** Throws unless every point is a number within Reach of the origin. */
void requireWithinReach(const std::vector<Polygon2>& contours)
{
  for (const Polygon2& contour : contours)
    for (const Point2& p : contour)
      if (!(std::abs(p.x) <= Reach && std::abs(p.y) <= Reach))
      {
        std::ostringstream message;
        message << "a contour point lies " << std::max(std::abs(p.x), std::abs(p.y))
                << " mm from the origin, beyond the 1 km any anatomy lies within";
        throw Error(message.str());
      }
}

ClipperLib::Paths toPaths(const std::vector<Polygon2>& contours)
{
  requireWithinReach(contours);
  ClipperLib::Paths paths;
  for (const Polygon2& contour : contours)
  {
    ClipperLib::Path path;
    path.reserve(contour.size());
    for (const Point2& p : contour)
      path.push_back({ static_cast<ClipperLib::cInt>(std::llround(p.x * Scale)),
                       static_cast<ClipperLib::cInt>(std::llround(p.y * Scale)) });
    paths.push_back(std::move(path));
  }
  return paths;
}

ClipperLib::Paths offset(const ClipperLib::Paths& paths, double delta)
{
  // Miter joins: corners stay corners, so growing and shrinking back returns the same polygon
  // wherever nothing narrower than the channel width was closed.
  ClipperLib::ClipperOffset offsetter(8.0);
  offsetter.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths result;
  offsetter.Execute(result, delta * Scale);
  return result;
}

std::string heights(const std::vector<double>& z)
{
  std::ostringstream text;
  text.precision(5);
  text << "z = ";
  for (std::size_t k = 0; k < z.size() && k < 5; ++k)
    text << (k ? ", " : "") << z[k];
  if (z.size() > 5)
    text << ", ...";
  text << " mm";
  return text.str();
}

/** Whether two contour edges cross properly (each passes through the other's interior), rather
 *  than touch or lie along each other as a keyhole's channel does. Exact predicates. */
bool properCrossing(const std::vector<Polygon2>& contours, const ContourEdge& e, const ContourEdge& f)
{
  auto ends = [&](const ContourEdge& edge)
  {
    const Polygon2& c = contours[edge.contour];
    return std::pair<const Point2&, const Point2&>(c[edge.edge], c[(edge.edge + 1) % c.size()]);
  };
  const auto [a, b] = ends(e);
  const auto [c, d] = ends(f);
  return orientation(a, b, c) * orientation(a, b, d) < 0 && orientation(c, d, a) * orientation(c, d, b) < 0;
}

std::string slices(std::size_t count)
{
  return std::to_string(count) + (count == 1 ? " slice" : " slices");
}

} // namespace

std::string ContourRepairReport::summary(double channelWidth) const
{
  std::ostringstream text;
  if (!crossingSlices.empty())
    text << "contours crossing in " << slices(crossingSlices.size()) << " (" << heights(crossingSlices)
         << ") repaired by the even-odd rule";
  if (!channelSlices.empty())
    text << (crossingSlices.empty() ? "" : "; ") << "keyholes (contours running into their holes and back), touching "
         << "contours or channels under " << channelWidth << " mm split or closed in " << slices(channelSlices.size())
         << " (" << heights(channelSlices) << ")";
  return text.str();
}

std::vector<Polygon2> evenOddRegion(const std::vector<Polygon2>& contours, const ContourRepairOptions& options)
{
  ClipperLib::Clipper clipper;
  clipper.AddPaths(toPaths(contours), ClipperLib::ptSubject, true);
  ClipperLib::Paths region;
  clipper.Execute(ClipperLib::ctUnion, region, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  // Closing (grow, then shrink a little further): channels narrower than the width vanish, and
  // pieces that met at a point come apart.
  const double half = 0.5 * options.channelWidth;
  ClipperLib::Paths closed = offset(offset(region, half), -(half + Separation));
  ClipperLib::Clipper cleaner;
  cleaner.StrictlySimple(true);
  cleaner.AddPaths(closed, ClipperLib::ptSubject, true);
  ClipperLib::Paths simple;
  cleaner.Execute(ClipperLib::ctUnion, simple, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

  std::vector<Polygon2> result;
  // Crumbs of a crossing: under the channel's square, or under a square millimetre and a hundredth
  // of the slice's largest piece (the loops a contour drawn back and forth over itself leaves).
  double largest = 0.0;
  for (const ClipperLib::Path& path : simple)
    largest = std::max(largest, std::abs(ClipperLib::Area(path)));
  const double smallest = std::max(options.channelWidth * options.channelWidth * Scale * Scale,
                                   std::min(Scale * Scale, 0.01 * largest));
  for (const ClipperLib::Path& path : simple)
  {
    if (path.size() < 3 || std::abs(ClipperLib::Area(path)) < smallest)
      continue;
    Polygon2 contour;
    contour.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path)
      contour.push_back({ static_cast<double>(p.X) / Scale, static_cast<double>(p.Y) / Scale });
    result.push_back(std::move(contour));
  }
  return result;
}

namespace
{
/** Whether closing the slice's channels (evenOddRegion) would keep as many contours as it has, so
 *  that the slice is kept as given without running it: nothing crosses, no two edges other than
 *  consecutive ones come within the channel width (the only places a closing joins or splits
 *  contours), and no contour is small enough to be dropped as a crumb. Most slices of a structure
 *  set are such; the closing's offsets were most of reading one. */
bool keptWithoutClosing(const std::vector<Polygon2>& contours, const ContourRepairOptions& options)
{
  requireWithinReach(contours); // a point that is no number, or absurdly far, is an error either way
  const double smallest = options.channelWidth * options.channelWidth;
  for (const Polygon2& contour : contours)
    if (contour.size() < 3 || std::abs(0.5 * twiceSignedArea(contour)) < 2.0 * smallest)
      return false;
  // Edges of one contour that are neighbours along it come that close on any contour whose points
  // are closer than the width (an export at 0.005 mm: every edge and the next but one), where no
  // channel is; a channel's two sides lie a hole's perimeter apart along the contour. Counted as
  // channels, such a contour went through Clipper's strictly-simple pass, quadratic in its points
  // (50,000 points: 5 s).
  const double gap = options.channelWidth + 2.0 * Separation;
  std::vector<std::vector<double>> along(contours.size());
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    along[c].push_back(0.0);
    for (std::size_t e = 0; e < contours[c].size(); ++e)
    {
      const Point2& a = contours[c][e];
      const Point2& b = contours[c][(e + 1) % contours[c].size()];
      along[c].push_back(along[c].back() + std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)));
    }
  }
  auto touch = [&](const ContourEdge& e, const ContourEdge& f)
  {
    const Polygon2& c = contours[e.contour];
    const Point2 &a = c[e.edge], &b = c[(e.edge + 1) % c.size()], &p = c[f.edge], &q = c[(f.edge + 1) % c.size()];
    return properCrossing(contours, e, f) ||
           std::min({ distanceToSegment(a, p, q), distanceToSegment(b, p, q), distanceToSegment(p, a, b),
                      distanceToSegment(q, a, b) }) == 0.0;
  };
  for (const auto& [e, f] : contourEdgesWithin(contours, gap))
  {
    if (e.contour != f.contour)
      return false;
    const std::vector<double>& s = along[e.contour];
    const double apart = std::abs(s[f.edge] - s[e.edge]);
    const double lengths = (s[e.edge + 1] - s[e.edge]) + (s[f.edge + 1] - s[f.edge]);
    if (std::min(apart, s.back() - apart) > lengths + 2.0 * gap || touch(e, f))
      return false; // a channel, or a loop drawn over itself
  }
  return true;
}
} // namespace

ContourStack repairContours(const ContourStack& stack, const ContourRepairOptions& options, ContourRepairReport* report)
{
  ContourStack result = stack;
  ContourRepairReport found;
  for (Slice& slice : result.slices)
  {
    if (slice.contours.empty() || keptWithoutClosing(slice.contours, options))
      continue;
    const auto crossings = contourCrossings(slice.contours);
    const bool crossing = std::any_of(crossings.begin(), crossings.end(), [&](const auto& pair)
                                      { return properCrossing(slice.contours, pair.first, pair.second); });
    std::vector<Polygon2> region = evenOddRegion(slice.contours, options);
    if (crossing)
      found.crossingSlices.push_back(slice.z);
    else if (!crossings.empty() || region.size() != slice.contours.size())
      found.channelSlices.push_back(slice.z);
    else
      continue; // kept exactly as given
    slice.contours = std::move(region);
  }
  if (report)
    *report = found;
  return result;
}

} // namespace slicemesh

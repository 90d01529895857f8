#include "Contours/ContourStacking.h"

#include "Core/PlanarGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace slicemesh
{
namespace
{

constexpr double Pi = 3.14159265358979323846;

/** A vector to compute with; the interface keeps Vector3, a plain array. */
using Vec = Eigen::Vector3d;

Vec asVector(const Point3& p)
{
  return { p.x, p.y, p.z };
}

bool samePoint(const Point3& a, const Point3& b)
{
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

/** The contour without points that repeat the one before them: a closing point that repeats the
 *  first (many files store it) and points stored twice in a row (some exports do). Left in, each
 *  is an edge of no length, which the repair would report as a keyhole in every slice. */
Polygon3 withoutRepeatedPoints(const Polygon3& contour)
{
  Polygon3 kept;
  kept.reserve(contour.size());
  for (const Point3& p : contour)
    if (kept.empty() || !samePoint(kept.back(), p))
      kept.push_back(p);
  while (kept.size() > 1 && samePoint(kept.front(), kept.back()))
    kept.pop_back();
  return kept;
}

/** An in-plane orthonormal basis (u, v) with u x v = normal: u from the patient axis most
 *  perpendicular to the normal, so axial contours keep x along L and y along P. */
std::pair<Vec, Vec> inPlaneBasis(const Vec& normal)
{
  const Vec axis = std::abs(normal[0]) < 0.9 ? Vec::UnitX() : Vec::UnitY();
  const Vec u = (axis - axis.dot(normal) * normal).normalized();
  return { u, normal.cross(u) };
}

/** Whether two contours of one slice are the same polygon (in either direction, from any start). */
bool sameContour(const Polygon2& a, const Polygon2& b, double tolerance)
{
  const std::size_t n = a.size();
  if (n != b.size() || n == 0)
    return false;
  std::size_t start = 0;
  for (std::size_t j = 1; j < n; ++j)
    if (distance(a[0], b[j]) < distance(a[0], b[start]))
      start = j;
  for (int direction : { 1, -1 })
  {
    bool same = true;
    for (std::size_t i = 0; i < n && same; ++i)
    {
      const std::size_t j = (start + n + static_cast<std::size_t>(direction) * i) % n;
      same = distance(a[i], b[j]) <= tolerance;
    }
    if (same)
      return true;
  }
  return false;
}

std::string millimetres(double value)
{
  std::ostringstream text;
  text.precision(4);
  text << value << " mm";
  return text.str();
}

/** A drawn contour's points lie in its plane to the rounding of their coordinates (a hundredth of a
 *  millimetre in a planning system's files): farther off, it is not the planar contour it claims. */
constexpr double maxOffPlane = 0.1;

/** The mean of the contour's points: the products of the normals are taken about it, since far
 *  from the origin they would lose the digits that matter. */
Vec centreOf(const Polygon3& contour)
{
  Vec centre = Vec::Zero();
  for (const Point3& p : contour)
    centre += asVector(p);
  return centre / static_cast<double>(contour.size());
}

/** newellNormal, as a vector to compute with. */
Vec newellVector(const Polygon3& contour)
{
  Vec normal = Vec::Zero();
  if (contour.size() < 3)
    return normal;
  const Vec centre = centreOf(contour);
  for (std::size_t i = 0; i < contour.size(); ++i)
  {
    const Point3& p = contour[i];
    const Point3& q = contour[(i + 1) % contour.size()];
    const double px = p.x - centre[0], py = p.y - centre[1], pz = p.z - centre[2];
    const double qx = q.x - centre[0], qy = q.y - centre[1], qz = q.z - centre[2];
    normal[0] += (py - qy) * (pz + qz);
    normal[1] += (pz - qz) * (px + qx);
    normal[2] += (px - qx) * (py + qy);
  }
  return normal;
}

/** planeNormal, as a vector to compute with. */
Vec planeVector(const Polygon3& contour)
{
  const Vec newell = newellVector(contour);
  if (contour.size() < 3)
    return newell;
  // The triangles from the centroid to each edge, each turned to agree with the largest: they do
  // not cancel where the contour's lobes wind opposite ways (a symmetric figure eight, whose
  // Newell normal vanishes while it still spans a plane and, by the even-odd rule, two lobes).
  const Vec centre = centreOf(contour);
  std::vector<Vec> fan;
  std::size_t largest = 0;
  for (std::size_t i = 0; i < contour.size(); ++i)
  {
    const Vec a = asVector(contour[i]) - centre;
    const Vec b = asVector(contour[(i + 1) % contour.size()]) - centre;
    fan.push_back(a.cross(b));
    if (fan.back().norm() > fan[largest].norm())
      largest = fan.size() - 1;
  }
  Vec unsignedSum = Vec::Zero();
  for (const Vec& n : fan)
    unsignedSum += n.dot(fan[largest]) < 0.0 ? -n : n;
  // Newell's wherever it stands for the contour (any contour that does not cross itself, and most
  // that do): only a cancelling one is replaced.
  return newell.norm() > 1e-6 * unsignedSum.norm() ? newell : unsignedSum;
}

/** sliceNormalOf, as a vector to compute with. */
Vec sliceVector(const std::vector<Polygon3>& contours)
{
  std::vector<Vec> normals;
  std::size_t largest = 0;
  for (const Polygon3& contour : contours)
  {
    normals.push_back(planeVector(withoutRepeatedPoints(contour)));
    if (normals.back().norm() > normals[largest].norm())
      largest = normals.size() - 1;
  }
  if (normals.empty() || !(normals[largest].norm() > 0.0))
    throw Error("no contour encloses an area: the slice plane is undefined");
  const Vec reference = normals[largest].normalized();
  // Area-weighted (a Newell normal's length is twice the area), signs aligned to the largest
  // contour (windings are unreliable), contours tilted by more than 5 degrees left out.
  const double agree = std::cos(5.0 * Pi / 180.0);
  Vec sum = Vec::Zero();
  for (const Vec& n : normals)
  {
    const double length = n.norm();
    if (!(length > 0.0))
      continue;
    const double cosine = n.dot(reference) / length;
    if (std::abs(cosine) < agree)
      continue;
    sum += cosine < 0.0 ? -n : n;
  }
  const Vec normal = sum.normalized();
  Eigen::Index biggest = 0;
  normal.cwiseAbs().maxCoeff(&biggest);
  return normal[biggest] < 0.0 ? -normal : normal;
}

Vector3 asArray(const Vec& v)
{
  return { v[0], v[1], v[2] };
}

} // namespace

Vector3 newellNormal(const Polygon3& contour)
{
  return asArray(newellVector(contour));
}

Vector3 planeNormal(const Polygon3& contour)
{
  return asArray(planeVector(contour));
}

Vector3 sliceNormalOf(const std::vector<Polygon3>& contours)
{
  return asArray(sliceVector(contours));
}

double automaticPointSpacing(const ContourStack& stack)
{
  // In-plane edges as long as the slices are apart give the tiling's walls near-equilateral
  // triangles; a structure whose contours are small keeps at least 64 points around its median
  // contour, and none gets points closer than 0.5 mm.
  std::vector<double> perimeters;
  for (const Slice& slice : stack.slices)
    for (const Polygon2& contour : slice.contours)
      perimeters.push_back(perimeter(contour));
  return std::max(0.5, std::min(stack.sliceSpacing, median(std::move(perimeters), 64.0) / 64.0));
}

namespace
{

/** 10^-d for the fewest decimals d up to 9 of which every coordinate is a whole multiple, else 0. */
double decimalStep(const std::vector<Polygon3>& contours)
{
  constexpr int mostDecimals = 9;
  int decimals = 0;
  for (const Polygon3& contour : contours)
    for (const Point3& p : contour)
      for (const double c : { p.x, p.y, p.z })
      {
        // A coordinate read from d decimals is the double nearest to an integer times 10^-d: scaled
        // by 10^d it is that integer up to a few units of the double's last place.
        auto whole = [c](int d)
        {
          const double scaled = c * std::pow(10.0, d);
          return std::abs(scaled - std::round(scaled)) <=
                 1e-9 + 8.0 * std::numeric_limits<double>::epsilon() * std::abs(scaled);
        };
        while (decimals <= mostDecimals && !whole(decimals))
          ++decimals;
        if (decimals > mostDecimals)
          return 0.0;
      }
  return std::pow(10.0, -decimals);
}

/** Whether c is a single-precision number: its significand fits in a float's. Read from the bits
 *  (frexp), not by a round trip through float, which GCC 12's vectorizer at -O2 and -O3 was seen to
 *  drop (a test's coordinates came out unrounded). */
bool singlePrecision(double c)
{
  int exponent = 0;
  const double significand = std::ldexp(std::frexp(c, &exponent), std::numeric_limits<float>::digits);
  return significand == std::trunc(significand) && exponent <= std::numeric_limits<float>::max_exponent;
}

/** The single-precision spacing at the largest coordinate if every coordinate is a float, else 0. */
double singlePrecisionStep(const std::vector<Polygon3>& contours)
{
  double largest = 0.0;
  for (const Polygon3& contour : contours)
    for (const Point3& p : contour)
      for (const double c : { p.x, p.y, p.z })
      {
        if (!singlePrecision(c))
          return 0.0;
        largest = std::max(largest, std::abs(c));
      }
  return largest * static_cast<double>(std::numeric_limits<float>::epsilon());
}

} // namespace

double coordinateStep(const std::vector<Polygon3>& contours)
{
  const double decimal = decimalStep(contours);
  return decimal > 0.0 ? decimal : singlePrecisionStep(contours);
}

StackedContours stackContours(const std::vector<Polygon3>& contours, const ContourStackingOptions& options)
{
  StackedContours result;
  Vec normal = sliceVector(contours);
  if (options.sliceNormal)
  {
    const Vec given(options.sliceNormal->data());
    if (!(given.norm() > 0.0) || !std::isfinite(given.norm()))
      throw Error("the given slice normal is zero or not finite");
    const double cosine = std::min(1.0, std::abs(normal.dot(given)) / given.norm());
    result.normalDeviationDegrees = std::acos(cosine) * 180.0 / Pi;
    // Contours drawn on the image's slices lie on its planes up to the planner's rounding; its
    // direction is then exact where theirs is an estimate.
    result.givenNormalUsed = *result.normalDeviationDegrees <= options.maxNormalDeviationDegrees;
    if (result.givenNormalUsed)
      normal = given.normalized();
  }
  const auto [u, v] = inPlaneBasis(normal);

  struct Placed
  {
    double position = 0.0; ///< along the normal, mm
    Polygon2 contour;
  };
  std::vector<Placed> placed;
  std::size_t tilted = 0, arealess = 0, uneven = 0;
  double farthestOffPlane = 0.0;
  const double maxTiltCosine = std::cos(options.maxTiltDegrees * Pi / 180.0);
  for (const Polygon3& raw : contours)
  {
    const Polygon3 contour = withoutRepeatedPoints(raw);
    const Vec n = planeVector(contour);
    const double length = n.norm();
    if (contour.size() < 3 || !(length > 1e-12))
    {
      ++arealess;
      continue;
    }
    if (std::abs(n.dot(normal)) / length < maxTiltCosine)
    {
      ++tilted;
      continue;
    }
    Placed p;
    const Vec centre = centreOf(contour);
    double offPlane = 0.0; // the farthest point from the contour's own plane
    for (const Point3& point : contour)
    {
      const Vec x = asVector(point);
      p.position += x.dot(normal);
      p.contour.push_back({ x.dot(u), x.dot(v) });
      offPlane = std::max(offPlane, std::abs((x - centre).dot(n)) / length);
    }
    if (offPlane > maxOffPlane)
    {
      ++uneven;
      farthestOffPlane = std::max(farthestOffPlane, offPlane);
    }
    p.position /= static_cast<double>(contour.size());
    placed.push_back(std::move(p));
  }
  if (arealess > 0)
    result.notes.push_back(std::to_string(arealess) + " contour(s) with fewer than three points or no area skipped");
  if (tilted > 0)
  {
    std::ostringstream note;
    note << tilted << " contour(s) tilted by more than " << options.maxTiltDegrees
         << " degrees from the slice plane skipped";
    result.notes.push_back(note.str());
  }
  if (uneven > 0)
  {
    std::ostringstream note;
    note.precision(3);
    note << uneven << " contour(s) not flat: points up to " << farthestOffPlane
         << " mm off their own plane (each is taken in the slice plane, at its points' mean position)";
    result.notes.push_back(note.str());
  }
  if (placed.empty())
    throw Error("no closed planar contour with an area");
  std::stable_sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) { return a.position < b.position; });

  // Slices: contours within the tolerance of a slice's first contour share it.
  double tolerance = options.sliceTolerance;
  if (!(tolerance > 0.0))
  {
    // Planners round positions by up to a few hundredths of a millimetre; no slices are that close.
    std::vector<double> clearGaps;
    for (std::size_t i = 1; i < placed.size(); ++i)
      if (placed[i].position - placed[i - 1].position > 0.05)
        clearGaps.push_back(placed[i].position - placed[i - 1].position);
    tolerance = std::min(0.25, 0.25 * median(clearGaps, 1.0));
  }
  std::vector<std::vector<const Placed*>> groups;
  for (const Placed& p : placed)
  {
    if (groups.empty() || p.position - groups.back().front()->position > tolerance)
      groups.emplace_back();
    groups.back().push_back(&p);
  }

  std::size_t duplicates = 0;
  std::vector<Slice> slices;
  for (const auto& group : groups)
  {
    Slice slice;
    double sum = 0.0;
    for (const Placed* p : group)
    {
      sum += p->position;
      const bool repeated = std::any_of(slice.contours.begin(), slice.contours.end(),
                                        [&](const Polygon2& kept) { return sameContour(kept, p->contour, 1e-3); });
      if (repeated)
        ++duplicates;
      else
        slice.contours.push_back(p->contour);
    }
    slice.z = sum / static_cast<double>(group.size());
    result.contoursUsed += slice.contours.size();
    slices.push_back(std::move(slice));
  }
  if (duplicates > 0)
    result.notes.push_back(std::to_string(duplicates) + " contour(s) repeated in their slice dropped");

  std::vector<double> gaps;
  for (std::size_t k = 1; k < slices.size(); ++k)
    gaps.push_back(slices[k].z - slices[k - 1].z);
  double spacing = median(gaps, options.fallbackSliceSpacing);
  // Slices three or more of the set's apart (two drawn 50 mm apart among 2.5 mm ones) are where the
  // structure was drawn, not a structure of 50 mm slices: 25 mm caps beyond each and a 50 mm column
  // between them. Every other slice (twice the set's) stays the structure's own spacing, tiled across.
  auto severalSlicesOf = [&spacing](double slice)
  {
    const double steps = std::round(spacing / slice);
    return steps >= 3.0 && std::abs(spacing - steps * slice) <= 0.05 * slice;
  };
  // The image's spacing says nothing of contours that are not on its slices.
  if (options.expectedSliceSpacing > 0.0 && (!options.sliceNormal || result.givenNormalUsed))
  {
    const double expected = options.expectedSliceSpacing;
    const bool onItsSlices = gaps.empty() || severalSlicesOf(expected) ||
                             std::any_of(gaps.begin(), gaps.end(),
                                         [&](double gap) { return std::abs(gap - expected) <= 0.05 * expected; });
    if (onItsSlices)
      spacing = expected;
    else
      result.notes.push_back("no two slices of contours are one image slice (" + millimetres(expected) +
                             ") apart: their own spacing (" + millimetres(spacing) + ") is used");
  }
  else if (options.setSliceSpacing > 0.0 && !gaps.empty() && severalSlicesOf(options.setSliceSpacing))
    spacing = options.setSliceSpacing;
  if (!(spacing > 0.0))
  {
    std::ostringstream message;
    message << "all " << result.contoursUsed << " contour(s) lie in one slice (at " << millimetres(slices.front().z)
            << " along the normal) and the slice spacing is unknown: no thickness to mesh";
    throw Error(message.str());
  }
  if (slices.size() == 1)
    result.notes.push_back("all contours lie in one slice: meshed as a slab one slice spacing (" +
                           millimetres(spacing) + ") thick");
  if (!gaps.empty())
  {
    // Usual gaps only: a missing slice is reported below, not as unevenness.
    double smallest = spacing, largest = spacing;
    for (double gap : gaps)
      if (gap < 1.5 * spacing)
      {
        smallest = std::min(smallest, gap);
        largest = std::max(largest, gap);
      }
    if (largest - smallest > 0.05 * spacing)
      result.notes.push_back("uneven slice spacing: gaps from " + millimetres(smallest) + " to " +
                             millimetres(largest) + " (usual " + millimetres(spacing) + ")");
  }

  // A slice between two that are one spacing apart (a contour drawn on another image, or on a plane
  // the planner interpolated): the tiling takes it as a slice of the structure, so what the slices
  // on either side hold and it does not is closed at it. Meshed as drawn, but said: an organ drawn on
  // every slice is split in two there, for the sake of one contour beside it.
  // One note for all of them, naming the first: a stretch drawn on half-spacing slices has many.
  std::vector<char> between(slices.size(), 0);
  std::size_t firstBelow = 0, firstAbove = 0;
  for (std::size_t k = 0; k + 2 < slices.size(); ++k)
  {
    std::size_t j = k + 2; // the slice about one spacing above k, slices between them
    while (j + 1 < slices.size() && slices[j].z - slices[k].z < 0.95 * spacing)
      ++j;
    if (std::abs(slices[j].z - slices[k].z - spacing) > 0.05 * spacing)
      continue;
    if (std::find(between.begin(), between.end(), 1) == between.end())
      std::tie(firstBelow, firstAbove) = std::pair{ k, j };
    std::fill(between.begin() + static_cast<std::ptrdiff_t>(k + 1), between.begin() + static_cast<std::ptrdiff_t>(j), 1);
  }
  if (const auto count = std::count(between.begin(), between.end(), 1); count > 0)
  {
    std::ostringstream note;
    if (count == 1)
      note << "the slice at " << millimetres(slices[firstBelow + 1].z) << " lies between the slices at "
           << millimetres(slices[firstBelow].z) << " and " << millimetres(slices[firstAbove].z) << ", one spacing apart";
    else
      note << count << " slices lie between two slices one spacing apart, the first at "
           << millimetres(slices[firstBelow + 1].z) << " between the slices at " << millimetres(slices[firstBelow].z)
           << " and " << millimetres(slices[firstAbove].z);
    note << ": what those hold and it does not is closed on both sides of it (a structure drawn across it is "
            "split there)";
    result.notes.push_back(note.str());
  }

  // A gap of one missing slice is tiled across, as a planner interpolates; a longer one means the
  // structure stops and starts again: empty slices there close each piece on its own.
  for (std::size_t k = 0; k < slices.size(); ++k)
  {
    if (k > 0)
    {
      const double gap = slices[k].z - slices[k - 1].z;
      const long steps = std::lround(gap / spacing);
      if (steps >= 2)
      {
        std::ostringstream note;
        note << "gap of " << millimetres(gap) << " between the slices at " << millimetres(slices[k - 1].z) << " and "
             << millimetres(slices[k].z) << " (usual spacing " << millimetres(spacing) << "): ";
        if (steps == 2)
          note << "one slice missing, tiled across it";
        else
        {
          note << "the structure stops and starts again; each side is closed on its own";
          for (long step = 1; step < steps; ++step)
            result.stack.slices.push_back({ slices[k - 1].z + gap * static_cast<double>(step) / static_cast<double>(steps), {} });
        }
        result.notes.push_back(note.str());
      }
    }
    result.stack.slices.push_back(std::move(slices[k]));
  }
  result.stack.sliceSpacing = spacing;
  result.stack.coordinateStep = coordinateStep(contours);

  const double pointSpacing = options.pointSpacing > 0.0 ? options.pointSpacing : automaticPointSpacing(result.stack);
  result.spacing = { pointSpacing, pointSpacing, spacing };
  result.frame.origin = { 0.0, 0.0, 0.0 };
  result.frame.spacing = result.spacing;
  for (int row = 0; row < 3; ++row)
    result.frame.direction[row] = { u[row], v[row], normal[row] };
  return result;
}

double estimatedTilingTriangles(const ContourStack& stack, double pointSpacing)
{
  if (!(pointSpacing > 0.0))
    throw Error("estimatedTilingTriangles: the point spacing must be positive");
  auto pointsOf = [pointSpacing](const Slice& slice)
  {
    double length = 0.0;
    for (const Polygon2& contour : slice.contours)
      for (std::size_t i = 0; i < contour.size(); ++i)
      {
        const Point2& a = contour[i];
        const Point2& b = contour[(i + 1) % contour.size()];
        length += std::hypot(b.x - a.x, b.y - a.y);
      }
    return std::ceil(length / pointSpacing);
  };
  double triangles = 0.0;
  for (std::size_t k = 0; k < stack.slices.size(); ++k)
  {
    const double points = pointsOf(stack.slices[k]);
    triangles += 2.0 * points; // its caps where the slices beside it have none
    if (k + 1 < stack.slices.size() && points > 0.0)
    {
      const double rows = std::max(1.0, (stack.slices[k + 1].z - stack.slices[k].z) / pointSpacing);
      triangles += (points + pointsOf(stack.slices[k + 1])) * rows;
    }
  }
  return triangles;
}

} // namespace slicemesh

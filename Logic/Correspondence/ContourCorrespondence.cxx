#include "Correspondence/ContourCorrespondence.h"

#include "Contours/ContourNesting.h"
#include "Core/DisjointSets.h"
#include "Correspondence/PolygonProximity.h"

#include <algorithm>
#include <cmath>

namespace slicemesh
{

namespace
{

/** Whether each contour is a hole (odd nesting depth); contours too small to nest stay outer. */
std::vector<bool> holeFlags(const std::vector<Polygon2>& contours, std::vector<bool>& usable)
{
  std::vector<Polygon2> valid;
  std::vector<std::size_t> index;
  usable.assign(contours.size(), false);
  for (std::size_t i = 0; i < contours.size(); ++i)
    if (contours[i].size() >= 3)
    {
      valid.push_back(contours[i]);
      index.push_back(i);
      usable[i] = true;
    }
  const ContourNesting nesting = orientAndNest(valid);
  std::vector<bool> holes(contours.size(), false);
  for (std::size_t k = 0; k < index.size(); ++k)
    holes[index[k]] = nesting.isHole(k);
  return holes;
}

} // namespace

GroupShape CorrespondenceGroup::shape() const
{
  if (upper.empty())
    return GroupShape::LowerOnly;
  if (lower.empty())
    return GroupShape::UpperOnly;
  if (lower.size() == 1)
    return upper.size() == 1 ? GroupShape::OneToOne : GroupShape::OneToMany;
  return upper.size() == 1 ? GroupShape::ManyToOne : GroupShape::ManyToMany;
}

GroupContact CorrespondenceGroup::contact() const
{
  if (links.empty())
    return GroupContact::None;
  const auto overlaps = static_cast<std::size_t>(
    std::count_if(links.begin(), links.end(), [](const ContourLink& l) { return l.contact == ContactKind::Overlap; }));
  if (overlaps == links.size())
    return GroupContact::Overlap;
  return overlaps == 0 ? GroupContact::WithinDistance : GroupContact::Mixed;
}

bool CorrespondenceGroup::hasDistanceOnlyLink() const
{
  return std::any_of(links.begin(), links.end(),
                     [](const ContourLink& l) { return l.contact == ContactKind::WithinDistance; });
}

SlabCorrespondence matchContours(const std::vector<Polygon2>& lower, const std::vector<Polygon2>& upper,
                                 double distanceThreshold)
{
  if (!(distanceThreshold >= 0.0) || !std::isfinite(distanceThreshold))
    throw Error("contour correspondence: the distance threshold must be finite and not negative");
  SlabCorrespondence result;
  std::vector<bool> usableLower, usableUpper;
  const std::vector<bool> holeLower = holeFlags(lower, usableLower);
  const std::vector<bool> holeUpper = holeFlags(upper, usableUpper);

  std::vector<IndexedPolygon> indexedLower, indexedUpper;
  indexedLower.reserve(lower.size());
  indexedUpper.reserve(upper.size());
  for (const Polygon2& p : lower)
    indexedLower.emplace_back(p);
  for (const Polygon2& p : upper)
    indexedUpper.emplace_back(p);

  // Edges of the graph: every same-orientation pair whose boxes (grown by the threshold) meet.
  std::vector<ContourLink> links;
  for (std::size_t i = 0; i < lower.size(); ++i)
  {
    if (!usableLower[i])
      continue;
    for (std::size_t j = 0; j < upper.size(); ++j)
    {
      if (!usableUpper[j] || holeLower[i] != holeUpper[j] ||
          !indexedLower[i].box().overlaps(indexedUpper[j].box(), distanceThreshold))
        continue;
      if (indexedLower[i].box().overlaps(indexedUpper[j].box()))
      {
        ++result.overlapTests;
        if (regionsOverlap(indexedLower[i], indexedUpper[j]))
        {
          links.push_back({ i, j, ContactKind::Overlap, 0.0 });
          continue;
        }
      }
      if (distanceThreshold > 0.0)
      {
        ++result.distanceTests;
        const double d = boundaryDistance(indexedLower[i], indexedUpper[j], distanceThreshold);
        if (d <= distanceThreshold)
          links.push_back({ i, j, ContactKind::WithinDistance, d });
      }
    }
  }

  // Groups: connected components over lower indices [0, nl) and upper indices [nl, nl + nu).
  const std::size_t nl = lower.size(), nu = upper.size();
  DisjointSets sets(nl + nu);
  for (const ContourLink& link : links)
    sets.unite(link.lower, nl + link.upper);
  std::vector<long> groupOf(nl + nu, -1);
  for (std::size_t k = 0; k < nl + nu; ++k)
  {
    const bool usable = k < nl ? usableLower[k] : usableUpper[k - nl];
    if (!usable)
      continue;
    const std::size_t root = sets.find(k);
    if (groupOf[root] < 0)
    {
      groupOf[root] = static_cast<long>(result.groups.size());
      result.groups.emplace_back();
      result.groups.back().holes = k < nl ? holeLower[k] : holeUpper[k - nl];
    }
    CorrespondenceGroup& group = result.groups[static_cast<std::size_t>(groupOf[root])];
    if (k < nl)
      group.lower.push_back(k);
    else
      group.upper.push_back(k - nl);
  }
  for (const ContourLink& link : links)
    result.groups[static_cast<std::size_t>(groupOf[sets.find(link.lower)])].links.push_back(link);
  return result;
}

const char* toString(GroupShape shape)
{
  switch (shape)
  {
    case GroupShape::OneToOne:
      return "one-to-one";
    case GroupShape::OneToMany:
      return "one-to-many";
    case GroupShape::ManyToOne:
      return "many-to-one";
    case GroupShape::ManyToMany:
      return "many-to-many";
    case GroupShape::LowerOnly:
      return "lower only";
    case GroupShape::UpperOnly:
      return "upper only";
  }
  return "?";
}

const char* toString(GroupContact contact)
{
  switch (contact)
  {
    case GroupContact::None:
      return "none";
    case GroupContact::Overlap:
      return "overlap";
    case GroupContact::WithinDistance:
      return "within distance";
    case GroupContact::Mixed:
      return "mixed";
  }
  return "?";
}

} // namespace slicemesh

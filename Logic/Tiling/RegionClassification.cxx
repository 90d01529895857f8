// Step 4 of Documentation/Algorithm.md, second half, and the sectors of step 5: the region of each
// face of the overlay, the correspondences, the difference polygons, and the sectors around vertices
// common to both slices where the surface switches between them.
#include "Tiling/SlabOverlayState.h"

#include <algorithm>
#include <deque>

namespace slicemesh
{

using namespace slab;

void SlabOverlay::Impl::classify()
{
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info() = FaceData{};
  auto lowerParent = [&](int c) { return lower->nesting.parent[c]; };
  auto upperParent = [&](int c) { return upper->nesting.parent[c]; };

  // Flood fill from the outside: crossing a contour edge toggles membership of that slice's region
  // and steps in or out of that contour.
  std::deque<FaceHandle> queue;
  FaceHandle start = cdt.infinite_face();
  start->info().visited = true;
  queue.push_back(start);
  while (!queue.empty())
  {
    FaceHandle f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i)
    {
      FaceHandle g = f->neighbor(i);
      if (g->info().visited)
        continue;
      FaceData next = f->info();
      next.component = -1;
      if (f->is_constrained(i))
      {
        const OverlayEdge* e = edgeBetween(f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i)));
        if (!e)
          throw Error("slab overlay: a triangulation edge is not an edge of either slice");
        if (e->lower)
        {
          next.inLower = !next.inLower;
          next.lowerInnermost =
            next.lowerInnermost == e->lowerContour ? lowerParent(e->lowerContour) : e->lowerContour;
        }
        if (e->upper)
        {
          next.inUpper = !next.inUpper;
          next.upperInnermost =
            next.upperInnermost == e->upperContour ? upperParent(e->upperContour) : e->upperContour;
        }
      }
      next.visited = true;
      g->info() = next;
      queue.push_back(g);
    }
  }

  // Correspondence: a contour continues into the other slice where a face inside (for an outer
  // boundary) or inside its hole (for a hole) has the same status in the other slice.
  std::fill(lowerContinues.begin(), lowerContinues.end(), 0);
  std::fill(upperContinues.begin(), upperContinues.end(), 0);
  std::map<std::pair<int, int>, bool> pairs;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    const FaceData& info = f->info();
    if (info.inLower == info.inUpper)
    {
      if (info.lowerInnermost >= 0)
        lowerContinues[info.lowerInnermost] = 1;
      if (info.upperInnermost >= 0)
        upperContinues[info.upperInnermost] = 1;
      if (info.inLower)
        pairs[{ info.lowerInnermost, info.upperInnermost }] = true;
    }
  }
  correspondences.clear();
  for (const auto& entry : pairs)
    correspondences.push_back(entry.first);

  // Difference polygons: connected pieces of the symmetric difference, split by contour edges.
  components.clear();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info().inLower == f->info().inUpper || f->info().component >= 0)
      continue;
    const int id = static_cast<int>(components.size());
    Component component;
    component.lowerSide = f->info().inLower;
    std::vector<FaceHandle> stack{ f };
    f->info().component = id;
    while (!stack.empty())
    {
      FaceHandle g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i)
      {
        if (g->is_constrained(i))
        {
          const OverlayEdge* e = edgeBetween(g->vertex(CDT::cw(i)), g->vertex(CDT::ccw(i)));
          (edgeLevel(*e, component.lowerSide) == LowerLevel ? component.touchesLowerLevel
                                                             : component.touchesUpperLevel) = true;
          continue;
        }
        FaceHandle h = g->neighbor(i);
        if (!cdt.is_infinite(h) && h->info().component < 0)
        {
          h->info().component = id;
          stack.push_back(h);
        }
      }
    }
    components.push_back(component);
  }
  computeCapHeights();
}

void SlabOverlay::Impl::forgetCornerLevels()
{
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    f->info().cornerLevel = { NoLevel, NoLevel, NoLevel };
}

std::vector<Sector> SlabOverlay::Impl::sectorsAround(VertexHandle v)
{
  // Faces around v counter-clockwise; the edge after face f (v at index i) is (f, ccw(i)).
  std::vector<FaceHandle> ring;
  auto circulator = cdt.incident_faces(v), done = circulator;
  do
  {
    ring.push_back(circulator);
  } while (++circulator != done);
  const std::size_t n = ring.size();
  std::size_t first = n;
  for (std::size_t k = 0; k < n; ++k)
    if (ring[k]->is_constrained(CDT::ccw(ring[k]->index(v))))
    {
      first = k;
      break;
    }
  std::vector<Sector> sectors;
  if (first == n)
    return sectors;
  // Walk once around, starting just after a contour edge.
  Sector current;
  current.vertex = v;
  for (std::size_t step = 1; step <= n; ++step)
  {
    FaceHandle f = ring[(first + step) % n];
    const int i = f->index(v);
    current.faces.push_back(f);
    if (f->is_constrained(CDT::ccw(i)))
    {
      sectors.push_back(current);
      current = Sector{};
      current.vertex = v;
    }
    else
      current.fan.push_back(f->vertex(CDT::cw(i)));
  }
  for (Sector& s : sectors)
  {
    FaceHandle f0 = s.faces.front(), f1 = s.faces.back();
    if (!isDifference(f0))
      continue;
    const bool lowerSide = components[f0->info().component].lowerSide;
    const int i0 = f0->index(v), i1 = f1->index(v);
    // The contour edge before the first face is (v, f0->vertex(ccw(i0))), after the last (v, f1->vertex(cw(i1))).
    s.startLevel = edgeLevel(*edgeBetween(v, f0->vertex(CDT::ccw(i0))), lowerSide);
    s.endLevel = edgeLevel(*edgeBetween(v, f1->vertex(CDT::cw(i1))), lowerSide);
  }
  return sectors;
}

std::vector<Sector> SlabOverlay::Impl::mixedSectors(bool assignCornerLevels)
{
  std::vector<Sector> mixed;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    if (!vertices[v->info()].onBoth())
      continue;
    for (Sector& s : sectorsAround(v))
    {
      if (!inMixed(s.faces.front()))
        continue;
      if (s.startLevel != s.endLevel)
        mixed.push_back(s);
      else if (assignCornerLevels)
        for (FaceHandle f : s.faces)
          f->info().cornerLevel[f->index(v)] = s.startLevel;
    }
  }
  return mixed;
}

} // namespace slicemesh

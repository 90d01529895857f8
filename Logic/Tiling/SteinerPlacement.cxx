// Steps 6 to 8 of Documentation/Algorithm.md: Steiner points inside difference polygons. Chords flat
// on a slice plane are split, rows climb the slab and the domes' rims, and triangles whose smallest 3D
// angle is under the target get their 3D circumcentre.
#include "Tiling/SlabOverlayState.h"

#include "Core/PlanarGeometry.h"
#include "Core/SpatialHash.h"
#include "Measures/TriangleAngles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slicemesh
{

using namespace slab;

namespace
{

/** Points already placed, to keep new Steiner points a minimum 3D distance apart. */
class SpacingGrid
{
public:
  explicit SpacingGrid(double cell)
    : m_Cells(std::max(cell, 1e-9))
  {
  }
  void add(const Point3& p)
  {
    m_Cells.insert(Point2{ p.x, p.y }, static_cast<int>(m_Points.size()));
    m_Points.push_back(p);
  }
  bool hasPointWithin(const Point3& p, double radius) const
  {
    return m_Cells.anyIn(m_Cells.cellsWithin({ p.x, p.y }, radius), [&](int index) {
      const Point3& q = m_Points[index];
      const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
      return dx * dx + dy * dy + dz * dz < radius * radius;
    });
  }
  /** Adds p unless a point lies within radius of it; whether it did. */
  bool addIfApart(const Point3& p, double radius)
  {
    if (hasPointWithin(p, radius))
      return false;
    add(p);
    return true;
  }

private:
  SpatialHash m_Cells;
  std::vector<Point3> m_Points;
};

Point3 circumcenter(const Point3& a, const Point3& b, const Point3& c)
{
  // a + ((|u|^2 v - |v|^2 u) x (u x v)) / (2 |u x v|^2), u = b - a, v = c - a.
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double n2 = nx * nx + ny * ny + nz * nz;
  const double u2 = ux * ux + uy * uy + uz * uz, v2 = vx * vx + vy * vy + vz * vz;
  const double wx = u2 * vx - v2 * ux, wy = u2 * vy - v2 * uy, wz = u2 * vz - v2 * uz;
  return { a.x + (wy * nz - wz * ny) / (2 * n2), a.y + (wz * nx - wx * nz) / (2 * n2),
           a.z + (wx * ny - wy * nx) / (2 * n2) };
}

} // namespace

bool SlabOverlay::Impl::insertSteiner(const Point2& p, double z, MeshBuilder& mesh, double clearance)
{
  // Measured in 3D: a row point just above a contour in projection is fine, a point beside a contour
  // at that contour's own height makes a sliver.
  const auto within = [clearance](double flat, double dz) { return flat * flat + dz * dz < clearance * clearance; };
  if (clearance > 0.0 &&
      (within(lowerNearest->distanceWithin(p, clearance), z - z0) || within(upperNearest->distanceWithin(p, clearance), z1 - z)))
    return false;
  // Steiner points go strictly inside difference polygons: never on a contour edge, which the
  // neighbouring slab shares.
  CDT::Locate_type type;
  int index = 0;
  const Kernel::Point_2 point(p.x, p.y);
  FaceHandle f = locate(point, type, index);
  if (type == CDT::VERTEX || type == CDT::OUTSIDE_CONVEX_HULL || type == CDT::OUTSIDE_AFFINE_HULL)
    return false;
  if (type == CDT::EDGE && f->is_constrained(index))
    return false;
  if (!isDifference(f))
    return false;
  // A point a hair's breadth off a contour edge of its face (rows along a line that continues a
  // contour edge put points there up to rounding) makes a triangle of no width in projection that
  // no flip can remove: lifted, it stands vertical and its neighbour folds onto it, a fold that
  // rounding then turns into crossing triangles (seen after an oblique direction was applied).
  // Optional points only: a chord's midpoint is needed, and chords are not contour edges.
  if (clearance > 0.0 && type == CDT::FACE)
    for (int i = 0; i < 3; ++i)
    {
      if (!f->is_constrained(i))
        continue; // a sliver against an ordinary edge is flipped away by the Delaunay insertion
      const auto& a = f->vertex(CDT::cw(i))->point();
      const auto& b = f->vertex(CDT::ccw(i))->point();
      if (distanceToSegment(p, { a.x(), a.y() }, { b.x(), b.y() }) < 1e-3 * typicalEdge)
        return false;
    }
  // The new faces lie in the same difference polygon (insertion and the Delaunay flips it makes
  // never cross a constraint): they inherit its classification, and the rest of the overlay keeps
  // its own: the overlay is classified once, not again after each round of Steiner points.
  FaceData region = f->info();
  region.cornerLevel = { NoLevel, NoLevel, NoLevel };
  region.lifted = { -1, -1, -1 };
  VertexHandle v = cdt.insert(point, type, f, index);
  auto face = cdt.incident_faces(v), done = face;
  do
    face->info() = region;
  while (++face != done);
  OverlayVertex steiner;
  steiner.p = p;
  steiner.steinerId = mesh.addPoint(p.x, p.y, z);
  v->info() = static_cast<int>(vertices.size());
  vertices.push_back(steiner);
  addToVertexCells(v);
  locateHint = v;
  return true;
}

std::size_t SlabOverlay::Impl::liftFlatChords(MeshBuilder& mesh)
{
  // A chord of a difference polygon whose two ends lie on the same slice would be flat on that
  // slice's plane, where the neighbouring slab may lay its own triangles (GEOMETRY_NOTES, trap 3).
  // Split such chords by Steiner points at interpolated heights until none is left; do the same
  // for the fan edges where the surface must switch between the two slices at a common vertex,
  // so that switch always happens towards a Steiner point.
  std::size_t inserted = 0;
  for (int round = 0; round < 64; ++round)
  {
    forgetCornerLevels();
    std::vector<Point2> splits;
    for (const Sector& s : mixedSectors(true))
    {
      if (s.fan.empty())
      {
        FaceHandle f = s.faces.front();
        Point2 c{ 0.0, 0.0 };
        for (int i = 0; i < 3; ++i)
        {
          c.x += f->vertex(i)->point().x() / 3.0;
          c.y += f->vertex(i)->point().y() / 3.0;
        }
        splits.push_back(c);
        continue;
      }
      for (VertexHandle w : s.fan)
        if (!vertices[w->info()].isSteiner())
          splits.push_back({ 0.5 * (s.vertex->point().x() + w->point().x()),
                             0.5 * (s.vertex->point().y() + w->point().y()) });
    }
    for (const CDT::Edge& e : finiteEdgesInStableOrder(cdt))
    {
      FaceHandle f = e.first;
      const int i = e.second;
      if (f->is_constrained(i))
        continue;
      if (!needsLiftedChords(f))
        f = f->neighbor(i);
      if (cdt.is_infinite(f) || !needsLiftedChords(f))
        continue;
      // The edge's two ends, with their levels in face f (both faces of a chord agree on them).
      VertexHandle a = e.first->vertex(CDT::cw(i)), b = e.first->vertex(CDT::ccw(i));
      auto levelIn = [&](VertexHandle v) -> Level {
        const OverlayVertex& ov = vertices[v->info()];
        if (ov.isSteiner())
          return NoLevel;
        if (isCapFace(f))
          return components[f->info().component].capLevel();
        if (!ov.onBoth())
          return singleLevel(ov);
        return static_cast<Level>(f->info().cornerLevel[f->index(v)]);
      };
      const Level la = levelIn(a), lb = levelIn(b);
      if (la != NoLevel && la == lb)
        splits.push_back({ 0.5 * (a->point().x() + b->point().x()), 0.5 * (a->point().y() + b->point().y()) });
    }
    if (splits.empty())
      return inserted;
    std::sort(splits.begin(), splits.end(),
              [](const Point2& p, const Point2& q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); });
    for (std::size_t s = 0; s < splits.size(); ++s)
    {
      if (s > 0 && splits[s].x == splits[s - 1].x && splits[s].y == splits[s - 1].y)
        continue;
      const Point2& p = splits[s];
      const FaceHandle f = faceFor(p);
      if (isDifference(f))
        inserted += insertSteiner(p, steinerHeight(f, p), mesh);
    }
  }
  std::ostringstream message;
  message << "tiling between z = " << z0 << " and " << z1 << " mm did not settle";
  throw Error(message.str());
}

std::size_t SlabOverlay::Impl::addRows(MeshBuilder& mesh, double edgeLength)
{
  // Between a contour and the other slice's contour the surface climbs the slab; rows of Steiner
  // points at the spacing of the edge length let its triangles be about as tall as they are wide
  // in 3D (a 1 mm contour spacing under 3 mm slices would otherwise give slivers only).
  const double dz = z1 - z0;
  // Columns start from the contour vertices of one slice only, the one with more of them, so the
  // rows line up: the planar Delaunay triangulation of aligned rows is well shaped in 3D even where
  // the slope compresses the rows in projection; staggered rows from both sides are not.
  std::vector<VertexHandle> starts[2];
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    const Level level = singleLevel(vertices[v->info()]);
    if (level == NoLevel)
      continue;
    bool onMixed = false;
    auto face = cdt.incident_faces(v), done = face;
    do
      onMixed = onMixed || inMixed(face);
    while (++face != done && !onMixed);
    if (onMixed)
      starts[level].push_back(v);
  }
  const Level level = starts[LowerLevel].size() >= starts[UpperLevel].size() ? LowerLevel : UpperLevel;
  std::vector<std::pair<Point2, double>> rowPoints;
  for (VertexHandle v : starts[level])
  {
    const OverlayVertex& ov = vertices[v->info()];
    Point2 target;
    const double flat = (level == LowerLevel ? upperNearest : lowerNearest)->nearest(ov.p, &target);
    int m = static_cast<int>(std::lround(std::hypot(flat, dz) / edgeLength));
    // Rows closer than a few percent of the edge length in projection cannot be told apart by
    // the planar triangulation.
    m = std::min(m, static_cast<int>(std::floor(flat / (0.05 * edgeLength))));
    for (int r = 1; r < m; ++r)
    {
      const double t = static_cast<double>(r) / m;
      const Point2 p{ ov.p.x + t * (target.x - ov.p.x), ov.p.y + t * (target.y - ov.p.y) };
      rowPoints.emplace_back(p, interpolatedHeight(p));
    }
  }
  return insertRowPoints(rowPoints, mesh, edgeLength, [&](FaceHandle f) { return inMixed(f); });
}

std::size_t SlabOverlay::Impl::addCapRows(MeshBuilder& mesh, double edgeLength)
{
  // Rows of Steiner points parallel to each domed cap's contour, an edge length apart in 3D, so the
  // dome's rounded rim is tiled by well-shaped triangles; the flat top is filled by refinement.
  std::vector<std::pair<Point2, double>> rowPoints;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    if (vertices[v->info()].isSteiner())
      continue;
    // Inwards: towards the centroid of the vertex's cap faces.
    Point2 towards{ 0.0, 0.0 };
    int component = -1, count = 0;
    auto face = cdt.incident_faces(v), done = face;
    do
    {
      if (!cdt.is_infinite(face) && isCapFace(face) && needsLiftedChords(face))
      {
        component = face->info().component;
        for (int i = 0; i < 3; ++i)
        {
          towards.x += face->vertex(i)->point().x() / 3.0;
          towards.y += face->vertex(i)->point().y() / 3.0;
        }
        ++count;
      }
    } while (++face != done);
    if (count == 0)
      continue;
    const Point2 origin{ v->point().x(), v->point().y() };
    double dx = towards.x / count - origin.x, dy = towards.y / count - origin.y;
    const double length = std::hypot(dx, dy);
    if (length == 0.0)
      continue;
    dx /= length;
    dy /= length;
    const double rise = std::abs(capZ[component] - capLevelZ(component));
    // Along the quarter circle of radius `rise`, rows an edge length apart in arc length.
    const int rows = static_cast<int>(std::ceil(0.5 * M_PI * rise / edgeLength));
    for (int r = 1; r <= rows; ++r)
    {
      const double angle = 0.5 * M_PI * r / rows;
      const double inward = rise * (1.0 - std::cos(angle));
      const Point2 p{ origin.x + dx * inward, origin.y + dy * inward };
      const FaceHandle f = faceFor(p);
      if (!isCapFace(f) || f->info().component != component)
        continue;
      rowPoints.emplace_back(p, domeHeight(component, p));
    }
  }
  return insertRowPoints(rowPoints, mesh, edgeLength, [&](FaceHandle f) { return isCapFace(f); });
}

std::size_t SlabOverlay::Impl::insertRowPoints(const std::vector<std::pair<Point2, double>>& rowPoints,
                                               MeshBuilder& mesh, double edgeLength,
                                               const std::function<bool(FaceHandle)>& accepts)
{
  // Rows from neighbouring starts converge (on one nearest point of the other contour, towards a
  // dome's top): a point too close to one kept before it, or to a corner, would only make slivers.
  SpacingGrid placed(edgeLength);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (isDifference(f))
      for (int i = 0; i < 3; ++i)
        placed.add(approximateLift(f, i, mesh));
  std::size_t inserted = 0;
  for (const auto& [p, z] : rowPoints)
  {
    if (!placed.addIfApart({ p.x, p.y, z }, 0.6 * edgeLength))
      continue;
    const FaceHandle f = faceFor(p);
    if (!cdt.is_infinite(f) && accepts(f))
      inserted += insertSteiner(p, z, mesh, optionalClearance());
  }
  if (inserted > 0)
    forgetCornerLevels();
  return inserted;
}

std::size_t SlabOverlay::Impl::refineBadTriangles(MeshBuilder& mesh, double minAngle, double edgeLength,
                                                  std::size_t budget)
{
  // Delaunay refinement judged on the lifted triangles: a triangle whose smallest 3D angle is under
  // the target gets the projection of its 3D circumcentre, lifted by the interpolant. Points go
  // only inside difference polygons (contour edges are shared with the next slab and stay whole),
  // so triangles held by short contour edges may stay bad; the budget bounds the work.
  // The first round looks at every triangle; each later one only at the triangles around the
  // vertices the round before inserted or flipped: elsewhere nothing changed, and a triangle that
  // stayed bad had its candidate turned down already (the points placed only grow).
  std::size_t inserted = 0;
  const SmallestAngleBound good(minAngle);
  SpacingGrid placed(edgeLength);
  std::vector<VertexHandle> changed;
  for (int round = 0; round < 12 && inserted < budget; ++round)
  {
    std::vector<std::pair<Point2, double>> candidates; // point, the bad triangle's circumradius
    auto consider = [&](FaceHandle f)
    {
      if (!isDifference(f))
        return;
      const Point3 a = approximateLift(f, 0, mesh), b = approximateLift(f, 1, mesh), c = approximateLift(f, 2, mesh);
      if (round == 0)
      {
        placed.add(a);
        placed.add(b);
        placed.add(c);
      }
      if (good.metBy(a, b, c))
        return;
      const Point3 center = circumcenter(a, b, c);
      const double radius = std::hypot(center.x - a.x, center.y - a.y, center.z - a.z);
      if (!std::isfinite(radius) || radius < 0.3 * edgeLength)
        return;
      candidates.push_back({ { center.x, center.y }, radius });
    };
    if (round == 0)
      for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        consider(f);
    else
      for (const FaceHandle f : finiteFacesAround(cdt, changed))
        consider(f);
    const int firstNew = static_cast<int>(vertices.size());
    std::size_t added = 0;
    for (const auto& [p, radius] : candidates)
    {
      const FaceHandle f = faceFor(p);
      if (!isDifference(f))
        continue;
      const double z = steinerHeight(f, p);
      if (placed.hasPointWithin({ p.x, p.y, z }, 0.5 * radius))
        continue;
      if (insertSteiner(p, z, mesh, optionalClearance()))
      {
        placed.add({ p.x, p.y, z });
        ++added;
      }
    }
    if (added == 0)
      break;
    inserted += added;
    forgetCornerLevels();
    changed.clear();
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (v->info() >= firstNew)
        changed.push_back(v);
    std::sort(changed.begin(), changed.end(), [](VertexHandle x, VertexHandle y) { return x->info() < y->info(); });
    // Insertion restores planar Delaunay around each new point; restore the surface metric too.
    if (liftOptions && liftOptions->surfaceMetricFlips)
    {
      const std::vector<VertexHandle> newVertices = changed;
      flipTowardsSurfaceQuality(mesh, &newVertices, &changed);
    }
  }
  return inserted;
}

} // namespace slicemesh

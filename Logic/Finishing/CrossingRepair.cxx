#include "Finishing/CrossingRepair.h"

#include "Core/AreaNormal.h"
#include "Core/BoundingBox.h"
#include "Core/SpatialHash.h"
#include "Measures/SelfIntersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <unordered_map>

namespace slicemesh
{
namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using TrianglePairs = std::set<std::pair<std::size_t, std::size_t>>;

/** The operations the search for two in a row (undoneInTwoSteps) may judge in one repair: a real
 *  remesh fold took about 650; two solids through each other, whose hundreds of crossings no
 *  operation parts, took millions (a minute) without a bound. */
constexpr std::size_t twoStepJudgements = 16384;

/** One flip, collapse or vertex move: the triangles it removes and those it rewrites (slot, new corners). */
struct Operation
{
  bool collapse = false;
  bool move = false; ///< a vertex moved: its triangles take a new point
  std::vector<std::size_t> removed;
  std::vector<std::pair<std::size_t, Triangle>> rewritten;
};

/** An operation's outcome: the crossings it would leave, the new crossing pairs, and the smallest
 *  angle of its triangles (as a cosine: larger is narrower). */
struct Outcome
{
  std::size_t crossings = 0;
  std::vector<std::pair<std::size_t, std::size_t>> added;
  double largestCosine = 1.0;
};

double largestAngleCosine(const std::vector<Point3>& points, const Triangle& t)
{
  double largest = -1.0;
  for (int corner = 0; corner < 3; ++corner)
  {
    const Point3& p = points[static_cast<std::size_t>(t[corner])];
    const Point3& q = points[static_cast<std::size_t>(t[(corner + 1) % 3])];
    const Point3& r = points[static_cast<std::size_t>(t[(corner + 2) % 3])];
    const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
    const double vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
    const double lengths = std::sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz));
    if (lengths > 0.0)
      largest = std::max(largest, (ux * vx + uy * vy + uz * vz) / lengths);
  }
  return largest;
}

BoundingBox boxOf(const std::vector<Point3>& points, const Triangle& t)
{
  BoundingBox box;
  for (std::int32_t v : t)
    box.add(points[static_cast<std::size_t>(v)]);
  return box;
}

double dot(const Point3& a, const Point3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/** The triangles around the movable vertices and two rings beyond, each of those vertices' fan, and
 *  the crossings among them, while edges are flipped and collapsed and vertices moved. */
class LocalRepair
{
public:
  LocalRepair(TriangleMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& crossings,
              const std::vector<char>& movable, double edgeLength)
    : m_Mesh(mesh), m_Movable(movable), m_Changed(mesh.points.size(), 0), m_Edge(edgeLength), m_FirstNew(mesh.points.size()),
      m_Alive(mesh.triangles.size(), 1),
      m_Crossings(crossings.begin(), crossings.end()), m_Cells(2.0 * edgeLength)
  {
    // Two rings past the movable vertices: every triangle an operation there rewrites, and the
    // triangles around it that it could come to cross, have a corner in them.
    std::vector<char> near = movable;
    for (int ring = 0; ring < 2; ++ring)
    {
      std::vector<char> grown = near;
      for (const Triangle& t : mesh.triangles)
        if (near[static_cast<std::size_t>(t[0])] || near[static_cast<std::size_t>(t[1])] || near[static_cast<std::size_t>(t[2])])
          for (std::int32_t v : t)
            grown[static_cast<std::size_t>(v)] = 1;
      near.swap(grown);
    }
    // And the triangles of every crossing, whatever their corners: a pair is dropped only after both
    // of its triangles have been tested again.
    std::vector<char> crossing(mesh.triangles.size(), 0);
    for (const auto& [first, second] : crossings)
      crossing[first] = crossing[second] = 1;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    {
      bool inScope = crossing[t] != 0;
      for (std::int32_t v : mesh.triangles[t])
        if (near[static_cast<std::size_t>(v)])
        {
          m_Fan[v].push_back(t);
          inScope = true;
        }
      if (inScope)
      {
        m_Scope.push_back(t);
        index(t);
      }
    }
  }

  /** Repairs crossing after crossing while an operation leaves fewer; true when none is left. */
  bool run(CrossingRepair& done)
  {
    const std::size_t most = 8 * m_Crossings.size() + 16;
    TrianglePairs stuck; // no operation around them leaves fewer crossings, as the mesh is now
    for (std::size_t step = 0; step < most && !m_Crossings.empty(); ++step)
    {
      const auto next = std::find_if(m_Crossings.begin(), m_Crossings.end(), [&](const auto& pair) { return !stuck.count(pair); });
      if (next == m_Crossings.end())
        return false;
      // A copy: the two-step search replaces the set (undo) and with it the element `next` points at.
      const std::pair<std::size_t, std::size_t> crossing = *next;
      const auto [first, second] = crossing;
      std::optional<std::pair<Operation, Outcome>> best = widestFewer(candidatesAround(first, second), m_Crossings.size());
      if (best)
      {
        apply(best->first, best->second);
        count(best->first, done);
        stuck.clear();
      }
      else if (undoneInTwoSteps(first, second, done))
        stuck.clear();
      else
        stuck.insert(crossing);
    }
    return m_Crossings.empty();
  }

  /** The flips and collapses of the edges around a crossing's two triangles (the edges of every
   *  triangle at their corners), and the moves of those edges' vertices to and half way to the mean
   *  of their neighbours. */
  std::vector<Operation> candidatesAround(std::size_t first, std::size_t second)
  {
    std::vector<Operation> candidates;
    const std::set<std::pair<std::int32_t, std::int32_t>> edges = edgesAround({ first, second });
    std::set<std::int32_t> vertices;
    for (const auto& [u, v] : edges)
    {
      for (std::optional<Operation> operation : { flip(u, v), collapse(u, v), collapse(v, u) })
        if (operation)
          candidates.push_back(std::move(*operation));
      vertices.insert({ u, v });
    }
    for (std::int32_t u : vertices)
      for (double way : { 1.0, 0.5 })
        if (std::optional<Operation> operation = movedToNeighbours(u, way))
          candidates.push_back(std::move(*operation));
    return candidates;
  }

  /** Of the operations that leave fewer than `crossings` crossings, the one whose triangles are
   *  widest: a single flip can undo a fold and leave a needle, where a collapse beside it would not.
   *  (Undoing a fold can take a step that crosses something else on the way.) */
  std::optional<std::pair<Operation, Outcome>> widestFewer(std::vector<Operation> candidates, std::size_t crossings) const
  {
    std::optional<std::pair<Operation, Outcome>> best;
    for (Operation& operation : candidates)
    {
      std::optional<Outcome> outcome = judge(operation);
      if (outcome && outcome->crossings < crossings &&
          (!best || outcome->largestCosine < best->second.largestCosine ||
           (outcome->largestCosine == best->second.largestCosine && outcome->crossings < best->second.crossings)))
        best.emplace(std::move(operation), std::move(*outcome));
    }
    return best;
  }

  /** What an operation changes in the repair's state, to be put back if it leads nowhere. */
  struct Undo
  {
    std::unordered_map<std::int32_t, std::vector<std::size_t>> fan;
    TrianglePairs crossings;
    std::vector<std::pair<std::size_t, Triangle>> triangles; ///< every slot it removes or rewrites, as it was
  };

  Undo undoOf(const Operation& operation) const
  {
    Undo undo{ m_Fan, m_Crossings, {} };
    for (std::size_t t : operation.removed)
      undo.triangles.emplace_back(t, m_Mesh.triangles[t]);
    for (const auto& rewritten : operation.rewritten)
      undo.triangles.emplace_back(rewritten.first, m_Mesh.triangles[rewritten.first]);
    return undo;
  }

  void undo(Undo& before)
  {
    m_Fan.swap(before.fan);
    m_Crossings.swap(before.crossings);
    for (const auto& [t, corners] : before.triangles)
    {
      m_Mesh.triangles[t] = corners;
      m_Alive[t] = 1;
    }
  }

  /** A fold that no single operation improves, undone by two: the first leaving as many crossings
   *  (a flip that turns the fold's inner edge, so that a collapse or a move can then take it out),
   *  the second, around a crossing the first touched, leaving fewer. The first such pair of
   *  operations, each first operation tried in turn with the widest second. (A fold of the Colin27
   *  T1's surface, where a voxel edge pinches two sheets, took four such pairs.) */
  bool undoneInTwoSteps(std::size_t first, std::size_t second, CrossingRepair& done)
  {
    const std::size_t before = m_Crossings.size();
    std::vector<Operation> firsts = candidatesAround(first, second);
    if (!spend(firsts.size()))
      return false;
    for (Operation& operation : firsts)
    {
      std::optional<Outcome> outcome = judge(operation);
      if (!outcome || outcome->crossings > before)
        continue;
      Undo undoFirst = undoOf(operation);
      apply(operation, *outcome);
      // The second around a crossing of a triangle the first rewrote.
      std::set<std::size_t> rewritten;
      for (const auto& slot : operation.rewritten)
        rewritten.insert(slot.first);
      const std::vector<std::pair<std::size_t, std::size_t>> left(m_Crossings.begin(), m_Crossings.end());
      for (const auto& [one, other] : left)
      {
        if (!rewritten.count(one) && !rewritten.count(other))
          continue;
        std::vector<Operation> seconds = candidatesAround(one, other);
        if (!spend(seconds.size()))
        {
          undo(undoFirst);
          return false;
        }
        if (std::optional<std::pair<Operation, Outcome>> then = widestFewer(std::move(seconds), before))
        {
          apply(then->first, then->second);
          count(operation, done);
          count(then->first, done);
          return true;
        }
      }
      undo(undoFirst);
    }
    return false;
  }

  /** Takes `judgements` from what the two-step search may still judge; false if that is less. */
  bool spend(std::size_t judgements)
  {
    if (judgements > m_TwoStepBudget)
    {
      m_TwoStepBudget = 0;
      return false;
    }
    m_TwoStepBudget -= judgements;
    return true;
  }

  /** Each triangle of movable corners with an angle under narrowAngleDegrees flipped or collapsed
   *  away where that widens the narrowest angle it touches and makes no crossing; two sweeps. */
  void widenNarrowTriangles(CrossingRepair& done, double narrowAngleDegrees)
  {
    const double narrowCosine = std::cos(narrowAngleDegrees * M_PI / 180.0);
    for (int sweep = 0; sweep < 2; ++sweep)
      for (std::size_t t : m_Scope)
      {
        const Triangle corners = m_Mesh.triangles[t];
        if (!m_Alive[t] || !movable(corners[0]) || !movable(corners[1]) || !movable(corners[2]) ||
            largestAngleCosine(m_Mesh.points, corners) <= narrowCosine)
          continue;
        std::optional<std::pair<Operation, Outcome>> best;
        for (int i = 0; i < 3; ++i)
        {
          const std::int32_t u = corners[i], v = corners[(i + 1) % 3];
          for (int kind = 0; kind < 3; ++kind)
          {
            std::optional<Operation> operation = kind == 0 ? flip(u, v) : kind == 1 ? collapse(u, v) : collapse(v, u);
            if (!operation)
              continue;
            std::optional<Outcome> outcome = judge(*operation);
            if (outcome && outcome->added.empty() && outcome->crossings == m_Crossings.size() &&
                outcome->largestCosine < narrowestBefore(*operation) &&
                (!best || outcome->largestCosine < best->second.largestCosine))
              best.emplace(std::move(*operation), std::move(*outcome));
          }
        }
        if (best)
        {
          apply(best->first, best->second);
          count(best->first, done);
        }
      }
  }

  /** The mesh without the removed triangles and the vertices no triangle uses any more; `done`
   *  gets the vertices' former numbers and the crossing pairs left, in the triangles' new numbers. */
  void compact(CrossingRepair& done)
  {
    std::vector<std::int32_t> newNumber(m_Mesh.points.size(), -1);
    std::vector<std::size_t> newTriangle(m_Mesh.triangles.size());
    std::vector<Triangle> kept;
    kept.reserve(m_Mesh.triangles.size());
    for (std::size_t t = 0; t < m_Mesh.triangles.size(); ++t)
      if (m_Alive[t])
      {
        newTriangle[t] = kept.size();
        kept.push_back(m_Mesh.triangles[t]);
        for (std::int32_t v : m_Mesh.triangles[t])
          newNumber[static_cast<std::size_t>(v)] = 0;
      }
    std::vector<std::int32_t> former;
    std::vector<Point3> points; // at their size: grown by doubling, a large piece's were held twice over
    const auto used = static_cast<std::size_t>(std::count(newNumber.begin(), newNumber.end(), 0));
    former.reserve(used);
    points.reserve(used);
    done.changed.reserve(used);
    for (std::size_t v = 0; v < newNumber.size(); ++v)
      if (newNumber[v] == 0)
      {
        newNumber[v] = static_cast<std::int32_t>(former.size());
        former.push_back(v < m_FirstNew ? static_cast<std::int32_t>(v) : m_Origin[v - m_FirstNew]);
        points.push_back(m_Mesh.points[v]);
        done.changed.push_back(m_Changed[v]);
      }
    for (Triangle& t : kept)
      for (std::int32_t& v : t)
        v = newNumber[static_cast<std::size_t>(v)];
    m_Mesh.points = std::move(points);
    m_Mesh.triangles = std::move(kept);
    done.formerVertex = std::move(former);
    // Only triangles alive cross: apply drops the pairs of those it removes.
    for (const auto& [first, second] : m_Crossings)
      done.stillCrossing.emplace_back(newTriangle[first], newTriangle[second]);
  }

private:
  /** The edges (u < v) of the triangles around the corners of the given triangles. */
  std::set<std::pair<std::int32_t, std::int32_t>> edgesAround(std::initializer_list<std::size_t> triangles) const
  {
    std::set<std::pair<std::int32_t, std::int32_t>> edges;
    for (std::size_t t : triangles)
      for (std::int32_t corner : m_Mesh.triangles[t])
        for (std::size_t around : fan(corner))
        {
          const Triangle& a = m_Mesh.triangles[around];
          for (int i = 0; i < 3; ++i)
            edges.insert(std::minmax(a[i], a[(i + 1) % 3]));
        }
    return edges;
  }

  const std::vector<std::size_t>& fan(std::int32_t v) const
  {
    static const std::vector<std::size_t> none;
    const auto found = m_Fan.find(v);
    return found == m_Fan.end() ? none : found->second;
  }

  bool movable(std::int32_t v) const { return m_Movable[static_cast<std::size_t>(v)] != 0; }

  /** Whether u and v are at most two edge lengths apart: as far as the far corners of two
   *  triangles of the remesh's longest edges (4/3 of the length), whose diagonal a flip makes. */
  bool withinReach(std::int32_t u, std::int32_t v) const
  {
    const Point3 &p = m_Mesh.points[static_cast<std::size_t>(u)], &q = m_Mesh.points[static_cast<std::size_t>(v)];
    const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
    return dx * dx + dy * dy + dz * dz <= 4.0 * m_Edge * m_Edge;
  }

  /** The triangle with the directed edge u -> v, and its third corner; nothing if there is none. */
  std::optional<std::pair<std::size_t, std::int32_t>> triangleWithEdge(std::int32_t u, std::int32_t v) const
  {
    for (std::size_t t : fan(u))
    {
      const Triangle& a = m_Mesh.triangles[t];
      for (int i = 0; i < 3; ++i)
        if (a[i] == u && a[(i + 1) % 3] == v)
          return std::make_pair(t, a[(i + 2) % 3]);
    }
    return std::nullopt;
  }

  std::set<std::int32_t> neighbours(std::int32_t v) const
  {
    std::set<std::int32_t> around;
    for (std::size_t t : fan(v))
      for (std::int32_t w : m_Mesh.triangles[t])
        if (w != v)
          around.insert(w);
    return around;
  }

  /** Edge uv replaced by the other diagonal of its two triangles. */
  std::optional<Operation> flip(std::int32_t u, std::int32_t v) const
  {
    if (!movable(u) || !movable(v))
      return std::nullopt;
    const auto left = triangleWithEdge(u, v), right = triangleWithEdge(v, u);
    if (!left || !right || left->second == right->second)
      return std::nullopt;
    const std::int32_t a = left->second, b = right->second;
    if (!withinReach(a, b) || neighbours(a).count(b)) // too long, or the new edge is there already
      return std::nullopt;
    Operation flipped;
    flipped.rewritten = { { left->first, Triangle{ a, u, b } }, { right->first, Triangle{ b, v, a } } };
    return flipped;
  }

  /** Vertex u merged into v, which stays where it is. */
  std::optional<Operation> collapse(std::int32_t u, std::int32_t v) const
  {
    if (!movable(u) || !movable(v) || !withinReach(u, v))
      return std::nullopt;
    const auto left = triangleWithEdge(u, v), right = triangleWithEdge(v, u);
    if (!left || !right || left->second == right->second)
      return std::nullopt;
    // The link condition: u and v have no neighbours in common but the two across their edge, and
    // those keep at least three neighbours each.
    const std::set<std::int32_t> aroundU = neighbours(u), aroundV = neighbours(v);
    std::size_t common = 0;
    for (std::int32_t w : aroundU)
      common += aroundV.count(w);
    if (common != 2 || neighbours(left->second).size() < 4 || neighbours(right->second).size() < 4)
      return std::nullopt;
    Operation merged;
    merged.collapse = true;
    merged.removed = { left->first, right->first };
    replaceInFan(u, v, merged);
    return merged;
  }

  /** Vertex u moved `way` (1: all the way) towards the mean of its neighbours, where a fold around
   *  it untangles: its triangles take a new point (added to the mesh; u is left without triangles),
   *  within two edge lengths. */
  std::optional<Operation> movedToNeighbours(std::int32_t u, double way)
  {
    if (!movable(u) || fan(u).empty())
      return std::nullopt;
    const std::set<std::int32_t> around = neighbours(u);
    Point3 mean{ 0.0, 0.0, 0.0 };
    for (std::int32_t w : around)
    {
      const Point3& p = m_Mesh.points[static_cast<std::size_t>(w)];
      mean = { mean.x + p.x, mean.y + p.y, mean.z + p.z };
    }
    const double share = 1.0 / static_cast<double>(around.size());
    const Point3& from = m_Mesh.points[static_cast<std::size_t>(u)];
    mean = { from.x + way * (mean.x * share - from.x), from.y + way * (mean.y * share - from.y),
             from.z + way * (mean.z * share - from.z) };
    const auto moved = static_cast<std::int32_t>(m_Mesh.points.size());
    m_Mesh.points.push_back(mean); // left unused, and dropped by compact, unless the move is made
    m_Movable.push_back(1);
    m_Changed.push_back(0);
    m_Origin.push_back(static_cast<std::size_t>(u) < m_FirstNew ? u : m_Origin[static_cast<std::size_t>(u) - m_FirstNew]);
    if (!withinReach(u, moved))
      return std::nullopt;
    Operation operation;
    operation.move = true;
    replaceInFan(u, moved, operation);
    return operation;
  }

  /** Rewrites u's triangles that the operation keeps with w for u: a collapse into w and a move to the
   *  new point w differ only in which triangles go and where w is. */
  void replaceInFan(std::int32_t u, std::int32_t w, Operation& operation) const
  {
    for (std::size_t t : fan(u))
      if (std::find(operation.removed.begin(), operation.removed.end(), t) == operation.removed.end())
      {
        Triangle corners = m_Mesh.triangles[t];
        std::replace(corners.begin(), corners.end(), u, w);
        operation.rewritten.emplace_back(t, corners);
      }
  }

  static void count(const Operation& operation, CrossingRepair& done)
  {
    ++(operation.collapse ? done.collapses : operation.move ? done.moves : done.flips);
  }

  /** The largest angle cosine (the narrowest angle) of the triangles the operation changes, as they are. */
  double narrowestBefore(const Operation& operation) const
  {
    double largest = -1.0;
    for (std::size_t t : operation.removed)
      largest = std::max(largest, largestAngleCosine(m_Mesh.points, m_Mesh.triangles[t]));
    for (const auto& rewritten : operation.rewritten)
      largest = std::max(largest, largestAngleCosine(m_Mesh.points, m_Mesh.triangles[rewritten.first]));
    return largest;
  }

  /** The operation's outcome, or nothing if it makes a degenerate triangle or turns one over. */
  std::optional<Outcome> judge(const Operation& operation) const
  {
    const std::vector<Point3>& points = m_Mesh.points;
    // Which way the surface faces there: the area normals of every triangle the operation changes,
    // summed. (Not each triangle's own: a folded triangle faces the wrong way itself.)
    Point3 facing{ 0.0, 0.0, 0.0 };
    const auto add = [&](std::size_t t)
    {
      const Point3 n = areaNormal(m_Mesh, m_Mesh.triangles[t]);
      facing = { facing.x + n.x, facing.y + n.y, facing.z + n.z };
    };
    for (std::size_t t : operation.removed)
      add(t);
    for (const auto& rewritten : operation.rewritten)
      add(rewritten.first);
    Outcome outcome;
    outcome.largestCosine = -1.0;
    std::vector<BoundingBox> boxes;
    // The volume the operation adds or takes away (tetrahedra from the origin): at most edge^3 / 8.
    double volumeChange = 0.0;
    const auto volumeOf = [&](const Triangle& t)
    {
      const Point3 &a = points[static_cast<std::size_t>(t[0])], &b = points[static_cast<std::size_t>(t[1])],
                   &c = points[static_cast<std::size_t>(t[2])];
      return (a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) + a.z * (b.x * c.y - b.y * c.x)) / 6.0;
    };
    for (std::size_t t : operation.removed)
      volumeChange -= volumeOf(m_Mesh.triangles[t]);
    for (const auto& [slot, corners] : operation.rewritten)
      volumeChange += volumeOf(corners) - volumeOf(m_Mesh.triangles[slot]);
    if (std::abs(volumeChange) > 0.125 * m_Edge * m_Edge * m_Edge)
      return std::nullopt;
    for (const auto& rewritten : operation.rewritten)
    {
      const Triangle& corners = rewritten.second; // not a structured binding: a lambda uses it
      const auto point = [&](int i)
      {
        const Point3& p = points[static_cast<std::size_t>(corners[i])];
        return Kernel::Point_3(p.x, p.y, p.z);
      };
      if (CGAL::collinear(point(0), point(1), point(2)))
        return std::nullopt;
      if (!(dot(areaNormal(m_Mesh, corners), facing) > 0.0))
        return std::nullopt;
      outcome.largestCosine = std::max(outcome.largestCosine, largestAngleCosine(points, corners));
      boxes.push_back(boxOf(points, corners));
    }
    const auto changed = [&](std::size_t t)
    {
      return std::find(operation.removed.begin(), operation.removed.end(), t) != operation.removed.end() ||
             std::any_of(operation.rewritten.begin(), operation.rewritten.end(), [&](const auto& r) { return r.first == t; });
    };
    outcome.crossings = static_cast<std::size_t>(std::count_if(m_Crossings.begin(), m_Crossings.end(), [&](const auto& pair)
                                                               { return !changed(pair.first) && !changed(pair.second); }));
    for (std::size_t i = 0; i < operation.rewritten.size(); ++i)
    {
      const auto& [slot, corners] = operation.rewritten[i];
      for (std::size_t other : trianglesNear(boxes[i]))
        if (m_Alive[other] && !changed(other) && boxes[i].overlaps(boxOf(points, m_Mesh.triangles[other])) &&
            trianglesCross(points, corners, m_Mesh.triangles[other]))
          outcome.added.emplace_back(std::minmax(slot, other));
      for (std::size_t j = i + 1; j < operation.rewritten.size(); ++j)
        if (trianglesCross(points, corners, operation.rewritten[j].second))
          outcome.added.emplace_back(std::minmax(slot, operation.rewritten[j].first));
    }
    outcome.crossings += outcome.added.size();
    return outcome;
  }

  void apply(const Operation& operation, const Outcome& outcome)
  {
    const auto leave = [&](std::size_t t)
    {
      for (std::int32_t v : m_Mesh.triangles[t])
      {
        const auto found = m_Fan.find(v);
        if (found != m_Fan.end())
          found->second.erase(std::remove(found->second.begin(), found->second.end(), t), found->second.end());
      }
    };
    const auto changedPair = [&](std::size_t t)
    {
      for (auto pair = m_Crossings.begin(); pair != m_Crossings.end();)
        pair = pair->first == t || pair->second == t ? m_Crossings.erase(pair) : std::next(pair);
    };
    const auto flag = [&](const Triangle& corners)
    {
      for (std::int32_t v : corners)
        m_Changed[static_cast<std::size_t>(v)] = 1;
    };
    for (std::size_t t : operation.removed)
      flag(m_Mesh.triangles[t]);
    for (const auto& [slot, corners] : operation.rewritten)
    {
      flag(m_Mesh.triangles[slot]);
      flag(corners);
    }
    for (std::size_t t : operation.removed)
    {
      leave(t);
      changedPair(t);
      m_Alive[t] = 0;
    }
    for (const auto& [slot, corners] : operation.rewritten)
    {
      leave(slot);
      changedPair(slot);
      m_Mesh.triangles[slot] = corners;
      index(slot);
      for (std::int32_t v : corners)
      {
        const auto found = m_Fan.find(v);
        if (found != m_Fan.end())
          found->second.push_back(slot);
        else if (static_cast<std::size_t>(v) >= m_FirstNew) // a moved vertex's new point
          m_Fan[v].push_back(slot);
      }
    }
    m_Crossings.insert(outcome.added.begin(), outcome.added.end());
  }

  /** Files triangle t under the cells of its box as it is now. A triangle's earlier places stay
   *  filed (an undo may give it its earlier corners back): a query checks the box it has. */
  void index(std::size_t t)
  {
    const BoundingBox box = boxOf(m_Mesh.points, m_Mesh.triangles[t]);
    if (!(m_Cells.cellCountOf(box) <= SpatialHash::mostCellsFiled))
      m_Oversized.push_back(t); // a long sliver: near every query, not filed under its many cells
    else
      m_Cells.insert(m_Cells.cellsOf(box), static_cast<int>(t));
  }

  /** The triangles of the scope (and those operations rewrote) filed under the cells of this box,
   *  each once, in increasing order: a candidate's own box is still to be checked. */
  std::vector<std::size_t> trianglesNear(const BoundingBox& box) const
  {
    std::vector<std::size_t> near;
    m_Cells.forEachIn(m_Cells.cellsOf(box),
                      [&](int t) { near.push_back(static_cast<std::size_t>(t)); });
    near.insert(near.end(), m_Oversized.begin(), m_Oversized.end());
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
  }

  TriangleMesh& m_Mesh;
  std::vector<char> m_Movable; ///< grows with the points moves add
  std::vector<char> m_Changed; ///< corners of the triangles operations removed or rewrote, before and after
  std::size_t m_FirstNew;       ///< the first point a move added
  std::vector<std::int32_t> m_Origin; ///< of each point a move added: the vertex it moved
  double m_Edge;
  std::vector<char> m_Alive;
  TrianglePairs m_Crossings;
  std::unordered_map<std::int32_t, std::vector<std::size_t>> m_Fan;
  std::vector<std::size_t> m_Scope;
  /** The scope's triangles by where they are (index), in cubes of two target edges, so that an
   *  operation is judged against the triangles near it only, not against the whole scope: a scope of
   *  every triangle of a piece (widenNarrowTrianglesLocally on a whole piece) made the judging
   *  quadratic, and so did columns of the plane on a tall wall (a body's skin: the triangles of
   *  every slice above and below). */
  SpatialHash m_Cells;
  std::vector<std::size_t> m_Oversized; ///< triangles over more than SpatialHash::mostCellsFiled cells
  std::size_t m_TwoStepBudget = twoStepJudgements;
};

} // namespace

CrossingRepair repairCrossingsLocally(TriangleMesh& mesh, const std::vector<std::pair<std::size_t, std::size_t>>& crossings,
                                      const std::vector<char>& movable, double edgeLength)
{
  CrossingRepair done;
  LocalRepair repair(mesh, crossings, movable, edgeLength);
  done.undone = repair.run(done);
  repair.compact(done);
  return done;
}

CrossingRepair widenNarrowTrianglesLocally(TriangleMesh& mesh, const std::vector<char>& movable, double edgeLength,
                                           double narrowAngleDegrees)
{
  CrossingRepair done;
  LocalRepair repair(mesh, {}, movable, edgeLength);
  repair.widenNarrowTriangles(done, narrowAngleDegrees);
  repair.compact(done);
  return done;
}

} // namespace slicemesh

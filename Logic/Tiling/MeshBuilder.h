// Accumulates the vertices and triangles of the output mesh as the slabs are tiled.
#ifndef MeshBuilder_h
#define MeshBuilder_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

/** The mesh being built. A slab tiled on its own thread builds on the shared contour points without
 *  changing them: its new points are numbered after them, as if the slab were the only one, and
 *  appendTo renumbers them where the slab's turn puts them. The result does not depend on which
 *  slab finished first. */
class MeshBuilder
{
public:
  MeshBuilder() = default;
  /** Builds on `base` (not copied; it must outlive the builder and not change meanwhile). */
  explicit MeshBuilder(const TriangleMesh& base)
    : m_Base(&base)
    , m_FirstId(static_cast<std::int32_t>(base.points.size()))
  {
  }

  std::int32_t addPoint(double x, double y, double z)
  {
    m_Mesh.points.push_back({ x, y, z });
    return m_FirstId + static_cast<std::int32_t>(m_Mesh.points.size() - 1);
  }
  void addTriangle(std::int32_t a, std::int32_t b, std::int32_t c) { m_Mesh.triangles.push_back({ a, b, c }); }
  const Point3& point(std::int32_t id) const
  {
    return id < m_FirstId ? m_Base->points[id] : m_Mesh.points[id - m_FirstId];
  }
  /** The mesh as built so far (with no base: every point; with a base: the new points only). */
  const TriangleMesh& mesh() const { return m_Mesh; }

  /** Appends this builder's new points and its triangles to `whole`, which holds the base's points
   *  first (with no base of its own). */
  void appendTo(MeshBuilder& whole) const
  {
    const std::int32_t shift = static_cast<std::int32_t>(whole.m_Mesh.points.size()) - m_FirstId;
    whole.m_Mesh.points.insert(whole.m_Mesh.points.end(), m_Mesh.points.begin(), m_Mesh.points.end());
    for (Triangle t : m_Mesh.triangles)
    {
      for (std::int32_t& id : t)
        id += id >= m_FirstId ? shift : 0;
      whole.m_Mesh.triangles.push_back(t);
    }
  }

  TriangleMesh release() { return std::move(m_Mesh); }

private:
  const TriangleMesh* m_Base = nullptr;
  std::int32_t m_FirstId = 0; ///< the id of the first point this builder adds
  TriangleMesh m_Mesh;
};

} // namespace slicemesh

#endif

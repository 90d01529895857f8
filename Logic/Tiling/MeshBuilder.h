// Accumulates the vertices and triangles of the output mesh as the slabs are tiled.
#ifndef MeshBuilder_h
#define MeshBuilder_h

#include "Core/SliceMeshTypes.h"

namespace slicemesh
{

class MeshBuilder
{
public:
  std::int32_t addPoint(double x, double y, double z)
  {
    m_Mesh.points.push_back({ x, y, z });
    return static_cast<std::int32_t>(m_Mesh.points.size() - 1);
  }
  void addTriangle(std::int32_t a, std::int32_t b, std::int32_t c) { m_Mesh.triangles.push_back({ a, b, c }); }
  const Point3& point(std::int32_t id) const { return m_Mesh.points[id]; }
  std::size_t triangleCount() const { return m_Mesh.triangles.size(); }
  TriangleMesh release() { return std::move(m_Mesh); }

private:
  TriangleMesh m_Mesh;
};

} // namespace slicemesh

#endif

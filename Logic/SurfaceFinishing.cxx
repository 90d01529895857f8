#include "SurfaceFinishing.h"

#include <algorithm>

namespace slicemesh
{
namespace
{

/** Why `candidate` may not replace the tiling; empty when it may. */
std::string rejection(const MeshValidation& candidate, const MeshValidation& tiling)
{
  if (!candidate.valid())
    return candidate.summary();
  if (candidate.components != tiling.components || candidate.eulerCharacteristic != tiling.eulerCharacteristic)
  {
    return "its topology changed (" + std::to_string(candidate.components) + " components and Euler characteristic " +
           std::to_string(candidate.eulerCharacteristic) + " instead of " + std::to_string(tiling.components) +
           " and " + std::to_string(tiling.eulerCharacteristic) + ")";
  }
  return {};
}

/** Puts back where `unsmoothed` has them the vertices of every triangle in a crossing pair and
 *  `rings` rings of triangles around them. Returns how many vertices moved back. */
std::size_t unsmoothAround(TriangleMesh& mesh, const TriangleMesh& unsmoothed,
                           const std::vector<std::pair<std::size_t, std::size_t>>& crossings, int rings)
{
  std::vector<bool> marked(mesh.points.size(), false);
  for (const auto& [first, second] : crossings)
    for (std::size_t t : { first, second })
      for (std::int32_t v : mesh.triangles[t])
        marked[static_cast<std::size_t>(v)] = true;
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<bool> grown = marked;
    for (const Triangle& t : mesh.triangles)
      if (marked[t[0]] || marked[t[1]] || marked[t[2]])
        for (std::int32_t v : t)
          grown[static_cast<std::size_t>(v)] = true;
    marked.swap(grown);
  }
  std::size_t moved = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (marked[v] && (mesh.points[v].x != unsmoothed.points[v].x || mesh.points[v].y != unsmoothed.points[v].y ||
                      mesh.points[v].z != unsmoothed.points[v].z))
    {
      mesh.points[v] = unsmoothed.points[v];
      ++moved;
    }
  return moved;
}

} // namespace

SurfaceFinishingOptions finishingOptionsFor(const std::array<double, 3>& spacing)
{
  SurfaceFinishingOptions options;
  options.remeshing.targetEdgeLength = automaticEdgeLength(spacing);
  options.smoothing.maxDisplacement = 0.3 * std::min({ spacing[0], spacing[1], spacing[2] });
  return options;
}

const char* finishName(SurfaceFinish finish)
{
  switch (finish)
  {
    case SurfaceFinish::Remeshed:
      return "Remeshed";
    case SurfaceFinish::Smoothed:
      return "Smoothed";
    case SurfaceFinish::Tiled:
      break;
  }
  return "Tiled";
}

FinishedSurface finishSurface(const TriangleMesh& tiling, const MeshValidation& tilingValidation,
                              const SurfaceFinishingOptions& options)
{
  FinishedSurface result{ tiling, tilingValidation, SurfaceFinish::Tiled, {} };
  if (options.finish == SurfaceFinish::Tiled)
    return result;
  if (!tilingValidation.valid())
  {
    result.fallback = "the tiling is not a valid surface, so it is not finished";
    return result;
  }

  if (options.finish == SurfaceFinish::Remeshed)
  {
    // Remeshed first, then smoothed: the umbrella operator is a fair Laplacian only on a regular
    // mesh. Smoothing the tiling's rows (edges of every length and direction) first, then
    // remeshing, left the surface 10-20% farther from the true one on the benchmark's phantoms.
    TriangleMesh remeshed;
    std::string why;
    try
    {
      remeshed = remeshSurface(tiling, options.remeshing);
    }
    catch (const Error& e)
    {
      why = e.what();
    }
    if (why.empty())
    {
      const TriangleMesh unsmoothed = remeshed;
      smoothSurface(remeshed, options.smoothing);
      MeshValidation validation = validateMesh(remeshed);
      // Two sheets a voxel apart (a thin gap between gyri, a thin wall) can be smoothed into each
      // other: there, and only there, the remesh's own positions are kept.
      std::size_t unsmoothedVertices = 0;
      for (int rings = 1; rings <= 4 && validation.selfIntersections > 0; rings *= 2)
      {
        unsmoothedVertices += unsmoothAround(remeshed, unsmoothed, selfIntersectingPairs(remeshed), rings);
        validation = validateMesh(remeshed);
      }
      why = rejection(validation, tilingValidation);
      if (why.empty())
      {
        FinishedSurface finished{ std::move(remeshed), validation, SurfaceFinish::Remeshed, {} };
        finished.unsmoothedVertices = unsmoothedVertices;
        return finished;
      }
    }
    result.fallback = "the remeshed surface was not kept: " + why;
  }

  TriangleMesh smoothed = tiling;
  smoothSurface(smoothed, options.smoothing);
  MeshValidation validation = validateMesh(smoothed);
  const std::string why = rejection(validation, tilingValidation);
  if (why.empty())
  {
    result.mesh = std::move(smoothed);
    result.validation = validation;
    result.finish = SurfaceFinish::Smoothed;
    return result;
  }
  result.fallback += (result.fallback.empty() ? "" : "; ") + std::string("the smoothed surface was not kept: ") + why;
  return result;
}

} // namespace slicemesh

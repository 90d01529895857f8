// Times the finishing's mesh-wide steps on a mesh from a file, in one process: the
// self-intersection test, the topology check and the smoothing (default options), each on the
// given number of threads, repeated; prints each step's fastest and median time. For comparing two
// builds on the same mesh (run each build's benchmark in turn), where a whole run's time is too
// noisy to show a change of a few percent in one step.
//   MeshStepBenchmark <mesh.vtp|.vtk|.stl|.ply|.obj> [repeats (5)] [threads (1)]
#include "Finishing/SurfaceSmoothing.h"
#include "MeshReader.h"
#include "Measures/MeshValidation.h"
#include "Measures/SelfIntersections.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace
{

void timeStep(const char* name, int repeats, const std::function<std::size_t()>& step)
{
  std::vector<double> seconds;
  std::size_t result = 0;
  for (int i = 0; i < repeats; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    result = step();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("| %s | %.4f | %.4f | %zu |\n", name, seconds.front(), seconds[seconds.size() / 2], result);
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: MeshStepBenchmark <mesh> [repeats] [threads]\n");
    return 2;
  }
  try
  {
    const slicemesh::TriangleMesh mesh = slicemesh::readMesh(argv[1]).mesh;
    const int repeats = argc > 2 ? std::max(1, std::stoi(argv[2])) : 5;
    const unsigned int threads = argc > 3 ? static_cast<unsigned int>(std::max(1, std::stoi(argv[3]))) : 1;
    std::printf("%zu triangles, %u thread(s), %d repeats\n\n| step | fastest (s) | median (s) | result |\n|---|---:|---:|---:|\n",
                mesh.triangles.size(), threads, repeats);
    timeStep("self-intersection test (crossing pairs)", repeats,
             [&] { return slicemesh::selfIntersectingTrianglePairs(mesh, threads).size(); });
    timeStep("topology check (components)", repeats,
             [&] { return slicemesh::validateMeshTopology(mesh).components; });
    timeStep("smoothing (vertices)", repeats,
             [&]
             {
               slicemesh::TriangleMesh smoothed = mesh;
               slicemesh::smoothSurface(smoothed, slicemesh::SurfaceSmoothingOptions(), threads);
               return smoothed.points.size();
             });
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "MeshStepBenchmark: %s\n", e.what());
    return 1;
  }
  return 0;
}

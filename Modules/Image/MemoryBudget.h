// How much memory a run may use, and a clear error instead of the OOM killer when it would not fit.
#ifndef MemoryBudget_h
#define MemoryBudget_h

#include <cstddef>
#include <optional>
#include <string>

namespace slicemesh
{

/** The memory the environment variable SLICEMESH_MEMORY_LIMIT_MB sets by hand, in bytes; empty
 *  when it is not set. Its value must be a plain positive number of MiB ("4096", "1.5"); anything
 *  else throws slicemesh::Error naming the variable and the value: read as far as it went, "8GB"
 *  limited a run to 8 MiB, "0x10" to 16 and "1e2" to 100, and "abc" or "0" removed the limit
 *  without a word. */
std::optional<double> memoryLimitBytes();

/** Bytes this process may still allocate: the smaller of the system's MemAvailable and the
 *  room left under the cgroup (container) memory limit. memoryLimitBytes(), when set, replaces the
 *  measurement (for tests, and to keep a shared machine responsive). Returns 0 when nothing can be
 *  measured. */
double availableMemoryBytes();

/** The memory a run needs at its peak for a volume of `voxels` voxels held at `volumeBytesPerVoxel`
 *  (the label maps as read, with what their reading holds beside them): that, the program itself
 *  and, per voxel, the mask and the contours and meshes of a large structure (measured: see
 *  MemoryBudget.cxx). */
double runMemoryBytes(double voxels, double volumeBytesPerVoxel);

/** What edges found in 3D hold per voxel at their peak besides the run (runMemoryBytes' second
 *  argument): the volume as float and the Canny filter's images. Measured: a byte volume of 320^3
 *  with one ball peaked at 693 MiB, an int16 one of 256 x 256 x 200 at 295 MiB: 19.2 and 17.6
 *  bytes a voxel with the program taken off. */
constexpr double edgesBytesPerVoxel = 12.0;

/** The memory a run needs at its peak to tile and finish about `triangles` tiled triangles (planar
 *  contours: estimatedTilingTriangles), the program included (measured: see MemoryBudget.cxx). */
double tilingMemoryBytes(double triangles);

/** Throws slicemesh::Error ("<what> needs about X GiB of memory; Y GiB are available ...") when
 *  neededBytes exceed availableMemoryBytes(). Does nothing when the available memory is unknown. */
void checkMemoryBudget(const std::string& what, double neededBytes);

} // namespace slicemesh

#endif

// MemAvailable from /proc/meminfo and the cgroup v2 / v1 limit: Linux's own accounting, read once
// per check (cheap: a few small files).
#include "MemoryBudget.h"

#include "Core/MeasureText.h"
#include "Core/SliceMeshTypes.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace slicemesh
{
namespace
{

/** The first number in a file, or -1 (missing file, "max", garbage). */
double numberInFile(const char* path)
{
  std::ifstream file(path);
  double value = -1.0;
  if (!(file >> value))
    return -1.0;
  return value;
}

double memAvailableBytes()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes)
  {
    std::getline(meminfo, unit);
    if (key == "MemAvailable:")
      return kilobytes * 1024.0;
  }
  return -1.0;
}

/** Room left under the cgroup's limit, or -1 when there is no limit. */
double cgroupRoomBytes()
{
  // cgroup v2
  const double limit2 = numberInFile("/sys/fs/cgroup/memory.max");
  if (limit2 > 0.0)
  {
    const double used = std::max(0.0, numberInFile("/sys/fs/cgroup/memory.current"));
    return std::max(0.0, limit2 - used);
  }
  // cgroup v1 (an unlimited group reports a huge number)
  const double limit1 = numberInFile("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  if (limit1 > 0.0 && limit1 < 1e17)
  {
    const double used = std::max(0.0, numberInFile("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
    return std::max(0.0, limit1 - used);
  }
  return -1.0;
}

std::string gibibytes(double bytes)
{
  constexpr double mebibyte = 1024.0 * 1024.0;
  std::ostringstream text;
  if (bytes < 1024.0 * mebibyte)
    text << std::fixed << std::setprecision(0) << std::ceil(bytes / mebibyte) << " MiB";
  else
    text << measureText(bytes / (1024.0 * mebibyte), 1) << " GiB";
  return text.str();
}

/** The program itself: libraries and their data, about 31 MB resident before any work (54 MB before
 *  DICOM and the snapshot became plugins; kept at 64 MB: the DICOM plugin adds about 20 MB). */
constexpr double bytesOfTheProgram = 64.0 * 1024.0 * 1024.0;

/** Per voxel besides the volume: the mask (1 byte) and the contours and meshes of the structures.
 *  The volume is dropped once the masks are cut and each mask once it is traced, so the meshes'
 *  share, the peak less the program (64 MB here) and the volume, was measured per voxel on the
 *  scaling benchmark's uchar label maps (2 threads, /usr/bin/time and farm-bench): 7.4-8.2 on the
 *  generated whole-body segmentation of 87 labels (512 x 512 x 400; 847-983 MiB in six runs), 3.1
 *  and 4.1 on one large ellipsoid (448 x 388 x 268) and a sphere of 256^3, 1.8 on a sphere of 512^3.
 *  The meshes grow with the surface, not the voxels: a crowded volume decides the figure, kept a
 *  tenth above the most measured so that no run passes the check only to be killed later (a single
 *  structure is over-estimated two to four times). */
constexpr double bytesPerVoxelOfARun = 9.0;

/** Per tiled triangle, through the finishing: the peak less the program on one ROI of two 10 mm
 *  squares 10 m apart (2 million tiled triangles by the estimate, 871 MB peak); 1 m apart, 140 bytes
 *  (0.2 million, 92 MB). Label maps of one structure, measured again since: 310-400 bytes a tiled
 *  triangle (spheres of 128^3 to 512^3, the large and the thick ellipsoid). */
constexpr double bytesPerTiledTriangle = 400.0;

} // namespace

double tilingMemoryBytes(double triangles)
{
  return bytesOfTheProgram + triangles * bytesPerTiledTriangle;
}

double runMemoryBytes(double voxels, double volumeBytesPerVoxel)
{
  return bytesOfTheProgram + voxels * (volumeBytesPerVoxel + bytesPerVoxelOfARun);
}

std::optional<double> memoryLimitBytes()
{
  const char* const variable = "SLICEMESH_MEMORY_LIMIT_MB";
  const char* set = std::getenv(variable);
  if (!set)
    return std::nullopt;
  const std::string value = set;
  // Digits with at most one decimal point, read by from_chars: the C locale's strtod would take a
  // hexadecimal number or an exponent, and another locale's would stop at the point.
  const bool plain = value.find_first_not_of("0123456789.") == std::string::npos &&
                     value.find_first_of("0123456789") != std::string::npos &&
                     std::count(value.begin(), value.end(), '.') <= 1;
  double mebibytes = 0.0;
  const char* const end = value.data() + value.size();
  const std::from_chars_result read = std::from_chars(value.data(), end, mebibytes, std::chars_format::fixed);
  if (!plain || read.ec != std::errc() || read.ptr != end || !std::isfinite(mebibytes) || mebibytes <= 0.0)
  {
    std::string shown = value.size() > 60 ? value.substr(0, 57) + "..." : value;
    std::replace_if(shown.begin(), shown.end(), [](unsigned char c) { return c < ' '; }, ' '); // on one line
    throw Error(std::string(variable) + " is '" + shown + "'; it takes a positive number of MiB, such as 4096 or 1.5");
  }
  return mebibytes * 1024.0 * 1024.0;
}

double availableMemoryBytes()
{
  if (const std::optional<double> limit = memoryLimitBytes())
    return *limit;
  const double available = memAvailableBytes();
  const double room = cgroupRoomBytes();
  if (available < 0.0)
    return room < 0.0 ? 0.0 : room;
  return room < 0.0 ? available : std::min(available, room);
}

void checkMemoryBudget(const std::string& what, double neededBytes)
{
  const double available = availableMemoryBytes();
  if (available <= 0.0 || neededBytes <= available)
    return;
  throw Error(what + " needs about " + gibibytes(neededBytes) + " of memory; " + gibibytes(available) +
              " are available (SliceMesh stops here rather than be killed for lack of memory)");
}

} // namespace slicemesh

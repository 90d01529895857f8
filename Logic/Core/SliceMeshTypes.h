// Value types shared by every stage of SliceMesh: contours in, triangles out.
// Geometry lives in the stack frame (see DESIGN.md): x, y in the slice plane
// in millimetres (index times spacing), z along the slice normal in millimetres.
#ifndef SliceMeshTypes_h
#define SliceMeshTypes_h

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace slicemesh
{

struct Point2
{
  double x = 0.0;
  double y = 0.0;
};

struct Point3
{
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

/** A closed polygon: the last point connects back to the first (not repeated). */
using Polygon2 = std::vector<Point2>;

/** The contours of one slice at height z (mm). Contours of a slice never cross. */
struct Slice
{
  double z = 0.0;
  std::vector<Polygon2> contours;
};

/** Slices in increasing z; consecutive slices bound one slab. */
struct ContourStack
{
  std::vector<Slice> slices;
  /** The thickness each slice stands for (mm), e.g. the image's slice spacing: caps at the ends of
   *  the stack lie half of it beyond the last contour. 0 means: the distance between the two end
   *  slices and their neighbours (a single slice then needs it set). */
  double sliceSpacing = 0.0;
  /** The step the contours' coordinates were rounded to where they were written (mm: 1e-6 for six
   *  decimals, about 4e-5 for single precision at 300 mm), 0 where they were not (traced from an
   *  image, or written in full). Points of adjacent slices drawn at one place differ by up to about
   *  that step on tilted planes. */
  double coordinateStep = 0.0;
};

/** Maps the stack frame to physical (LPS) space: p = origin + direction * (x, y, z).
 *  The columns of direction are the image's unit axis vectors. */
struct SliceFrame
{
  std::array<double, 3> origin{ 0.0, 0.0, 0.0 };
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  std::array<std::array<double, 3>, 3> direction{ { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
};

using Triangle = std::array<std::int32_t, 3>;

/** An indexed triangle mesh with shared vertices; triangles wind counter-clockwise seen from outside. */
struct TriangleMesh
{
  std::vector<Point3> points;
  std::vector<Triangle> triangles;
};

/** Thrown by library functions on bad input: a one-line message naming the input and the fault. */
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace slicemesh

#endif

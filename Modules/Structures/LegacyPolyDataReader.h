// The geometry of a legacy VTK polydata file (".vtk", ASCII or binary, the cell lists of format 4
// and the offsets and connectivity arrays of format 5), read by SliceMesh itself: VTK 9.1's legacy
// reader reads past the end of its buffers on malformed lists and headers, and a contour file is
// user input. Only what a planar-contour file needs is kept: points, polylines, polygons and the
// dataset's string fields; vertices and strips are read past, point and cell data are not read.
#ifndef LegacyPolyDataReader_h
#define LegacyPolyDataReader_h

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace slicemesh
{

/** What SliceMesh takes from a polydata file for its contours. */
struct PolyDataGeometry
{
  /** A legacy file's second line, its title (3D Slicer writes "SPACE=RAS" there). */
  std::string title;
  std::vector<std::array<double, 3>> points;
  /** Each cell's point ids, as in the file: not yet checked against the number of points. */
  std::vector<std::vector<std::int64_t>> lines, polygons;
  /** The first value of each string array of the dataset's FIELD data, by array name. */
  std::map<std::string, std::string> fieldStrings;
};

/** Reads the file, or throws slicemesh::Error with one line saying what is wrong where. A declared
 *  count larger than the file costs no memory: values are read as they come. */
PolyDataGeometry readLegacyPolyData(const std::string& path);

} // namespace slicemesh

#endif

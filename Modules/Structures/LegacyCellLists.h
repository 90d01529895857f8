// The cell lists of a legacy VTK file (format before 5), checked before VTK reads them: VTK 9.1's
// reader crashes on a list that ends before the number of values it declares (it closes the file
// on the error and reads on from it) and reads past a list whose cells run beyond its end.
#ifndef LegacyCellLists_h
#define LegacyCellLists_h

#include <optional>
#include <string>

namespace slicemesh
{

/** What is wrong with the first faulty VERTICES, LINES, POLYGONS or TRIANGLE_STRIPS list of the
 *  legacy VTK file (ASCII or binary): fewer values than declared, a cell count that is negative or
 *  runs past the list's end; empty when every list is whole or the file is of format 5 or later
 *  (offsets and connectivity arrays, which VTK checks itself). */
std::optional<std::string> legacyCellListFault(const std::string& path);

} // namespace slicemesh

#endif

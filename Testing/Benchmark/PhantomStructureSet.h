// One ROI's contours written as an RT structure set, for the contour accuracy benchmark. On its own:
// the phantoms' Vector3 (Eigen) and the structure set's (std::array) cannot meet in one file.
#ifndef PhantomStructureSet_h
#define PhantomStructureSet_h

#include "Core/SliceMeshTypes.h"

#include <string>
#include <vector>

namespace slicemesh
{

/** Writes the contours (each a closed polygon of one slice) as the one ROI ("Phantom", number 1) of
 *  an RTSTRUCT file. */
void writePhantomStructureSet(const std::string& path, const std::vector<std::vector<Point3>>& contours);

} // namespace slicemesh

#endif

// A minimal DICOM RT Structure Set from structures: what readRTStructureSet needs and what other
// DICOM RT readers expect of one, for tests, benchmarks and tools that make contours.
#ifndef StructureSetWriter_h
#define StructureSetWriter_h

#include "StructureSet.h"

namespace slicemesh
{

/** A contour item of any geometric type; CLOSED_PLANAR for the structures' own contours. */
struct ContourItem
{
  int roiNumber = 0;
  std::string geometricType = "CLOSED_PLANAR"; ///< CLOSED_PLANAR, OPEN_PLANAR, OPEN_NONPLANAR, POINT
  Polygon3 points;
  /** Written as the Contour Data in place of `points` when not empty, as it stands: a malformed
   *  value (a decimal comma, "nan") for the tests of reading one. */
  std::string contourData;
};

/** Writes the structures (each ROI's number, name, colour, contours as CLOSED_PLANAR items), then
 *  `extraItems`, as an RTSTRUCT file whose ROIs are in Frame of Reference `frameOfReference` (empty:
 *  a new UID). Throws slicemesh::Error when it cannot. */
void writeRTStructureSet(const std::string& path, const std::vector<PlanarStructure>& structures,
                         const std::vector<ContourItem>& extraItems = {}, const std::string& frameOfReference = {});

} // namespace slicemesh

#endif

// Settings of a run on a structure set or contour file: one mesh per ROI.
#ifndef ContourInputSettings_h
#define ContourInputSettings_h

#include "ContourRepair.h"
#include "StructureSet.h"

#include <string>
#include <vector>

namespace slicemesh::cli
{

struct ContourInputSettings
{
  /** The structure set or contour file; empty: the input is a volume. */
  std::string path;
  ContourFileKind kind = ContourFileKind::Automatic;
  /** ROI names or numbers to mesh; empty: every ROI. */
  std::vector<std::string> rois;
  ContourRepairOptions repair;
  bool enabled() const { return !path.empty(); }
};

} // namespace slicemesh::cli

#endif

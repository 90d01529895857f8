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
  /** The image the contours were drawn on (a volume file or DICOM series): its slice direction and
   *  spacing stack the contours when they lie on its slices. Empty: the contours' own. */
  std::string referenceImage;
  /** ROI names or numbers to mesh; empty: every ROI. */
  std::vector<std::string> rois;
  ContourRepairOptions repair;
  bool enabled() const { return !path.empty(); }
};

} // namespace slicemesh::cli

#endif

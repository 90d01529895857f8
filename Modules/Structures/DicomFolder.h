// What a DICOM export folder holds besides its image series: the structure sets and segmentations
// drawn on it. A planning system or PACS exports a patient's CT slices and RTSTRUCT (or SEG) into one
// folder.
#ifndef DicomFolder_h
#define DicomFolder_h

#include <cstddef>
#include <string>
#include <vector>

namespace slicemesh
{

struct DicomFolderContents
{
  std::vector<std::string> structureSets; ///< paths of the RT Structure Sets, in name order
  std::vector<std::string> segmentations; ///< paths of the DICOM Segmentations (SEG), in name order
  std::size_t otherDicomFiles = 0;        ///< DICOM files that are neither (image slices, ...)
};

/** The DICOM files directly in `folder` (not in its subfolders, as the series reader sees it), by
 *  their first bytes (a structure set as detectContourFileKind finds it, with or without the
 *  preamble; a segmentation by its SOP class in the file's meta information): a file that is not
 *  DICOM is not counted. Never throws on a file's content; an
 *  unreadable folder holds nothing. */
DicomFolderContents dicomFolderContents(const std::string& folder);

} // namespace slicemesh

#endif

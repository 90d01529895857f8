// Settings of a multi-label run: one mesh per label of a label map.
#ifndef MultiLabelSettings_h
#define MultiLabelSettings_h

#include <string>
#include <vector>

namespace slicemesh::cli
{

struct MultiLabelSettings
{
  /** One mesh per label instead of one mesh of the selection. */
  bool enabled = false;
  /** The labels to mesh, by value (segment number for a segmentation file) and by name (the colour
   *  table's or the file's, any case); both empty means every non-zero label of the volume. */
  std::vector<int> labels;
  std::vector<std::string> labelNames;
  /** Folder for the per-label files "<value>_<name>.<ext>" (ext of the output model); empty writes
   *  only the merged output model. */
  std::string outputDirectory;
  /** Colour table (Slicer .ctbl/.txt, FreeSurfer LUT, "value name" list) for names and colours. */
  std::string colorTable;
};

} // namespace slicemesh::cli

#endif

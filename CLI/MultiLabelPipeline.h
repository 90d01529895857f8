// One mesh per label of a label map: one pass to index the labels, then per label a cropped mask
// -> contours -> reconstruction -> validation -> its own file, and all of them merged into the
// output model with a per-triangle "Label" and "Color" (what 3D Slicer gets back).
#ifndef MultiLabelPipeline_h
#define MultiLabelPipeline_h

#include "SliceMeshPipeline.h"

namespace slicemesh::cli
{

struct LabelMeshOutcome
{
  int label = 0;
  std::string name;
  std::string path;             ///< the per-label file, empty when no folder was given
  MeshValidation validation;    ///< of the label's mesh
  std::size_t voxels = 0;
  double seconds = 0.0;
  std::string error;            ///< why the label failed; empty on success
};

/** Runs the labels in increasing order. A label whose meshing throws is reported (error) and
 *  skipped; the others are still written. The returned validation sums the labels' figures
 *  (triangles, volume, defects), so `valid()` holds when every label's mesh is valid. Throws
 *  PipelineFailure as runPipeline does; after writing, MeshingFailed names the failed labels. */
PipelineResult runMultiLabelPipeline(const PipelineSettings& settings, ProgressReporter& progress,
                                     std::vector<LabelMeshOutcome>* outcomes = nullptr);

} // namespace slicemesh::cli

#endif

// One mesh per label of a label map: one pass to index the labels, then per label a cropped mask
// -> contours -> reconstruction -> validation -> finishing -> its own file, all of them merged into the
// output model with a per-triangle "Label" and "Color" (what 3D Slicer gets back).
#ifndef MultiLabelPipeline_h
#define MultiLabelPipeline_h

#include "SliceMeshPipeline.h"

namespace slicemesh::cli
{

/** What happened to one label: its figures, file, and why it failed (QualityReport.h). */
using LabelMeshOutcome = LabelReport;

/** Runs the labels in increasing order. A label whose meshing throws is reported (error) and
 *  skipped; the others are still written. --minimumComponentVolume applies to each label's mask as
 *  in the single-label path (26-connected components); a label left empty by it is dropped with a
 *  warning (no file), and the run fails with EmptySegmentation only when every label is dropped.
 *  The returned validation sums the labels' figures (triangles, volume, defects), so `valid()`
 *  holds when every label's mesh is valid; the quality is combinedQuality's over the labels. The
 *  snapshot shows every label's mesh in its colour, the report lists every label. Throws
 *  PipelineFailure as runPipeline does; after writing, MeshingFailed names the failed labels. */
PipelineResult runMultiLabelPipeline(const PipelineSettings& settings, ProgressReporter& progress,
                                     std::vector<LabelMeshOutcome>* outcomes = nullptr);

} // namespace slicemesh::cli

#endif

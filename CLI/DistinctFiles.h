// The files a run reads and writes, each a file of its own: an output named as an input, or as
// another output, would overwrite it.
#ifndef DistinctFiles_h
#define DistinctFiles_h

#include "SliceMeshPipeline.h"

#include <string>

namespace slicemesh::cli
{

/** Throws PipelineFailure(BadArguments), one line naming both options and the path, when an output
 *  (the mesh, --report, --snapshot, --returnparameterfile) is the same file as an input (the input
 *  volume or contour file, the files a detached volume header names as its data, --inputContours or
 *  the structure set of a DICOM folder, --colorTable) or as another output. Paths are compared where
 *  they lead: links followed, as a write follows them, and "." and ".." resolved, whether or not the
 *  file exists yet. Nothing is written, and of the input only its header's text is read
 *  (detachedDataFiles). */
void requireDistinctFiles(const PipelineSettings& settings);

/** The same for `structureFile`, the mesh of a label or ROI to be written into --outputDirectory,
 *  against the files requireDistinctFiles compares; its name is known only once the input is read.
 *  The message starts with `whose` ("ROI 1 (PTV): "). */
void requireDistinctStructureFile(const PipelineSettings& settings, const std::string& structureFile,
                                  const std::string& whose);

} // namespace slicemesh::cli

#endif

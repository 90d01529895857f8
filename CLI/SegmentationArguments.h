// The segmentation and multi-label parameters of SliceMesh.xml, turned into pipeline settings.
#ifndef SegmentationArguments_h
#define SegmentationArguments_h

#include "CommandLine.h"
#include "SliceMeshPipeline.h"

namespace slicemesh::cli
{

/** Reads processing, denoising, window, Otsu classes, edge mode, seeds, hole filling, minimum area
 *  and the multiple-label parameters into settings. Throws PipelineFailure (BadArguments) on a malformed or inconsistent value. */
void readSegmentationArguments(const ParsedArguments& arguments, PipelineSettings& settings);

} // namespace slicemesh::cli

#endif

// How a pipeline step's failure reaches the user: as a PipelineFailure whose exit code names the
// kind of failure (unreadable input, empty segmentation, meshing, writing).
#ifndef PipelineStep_h
#define PipelineStep_h

#include "SliceMeshPipeline.h"

#include <exception>

namespace slicemesh::cli
{

/** Runs one step; a failure becomes a PipelineFailure with the given code. */
template <typename Step>
auto guarded(ExitCode code, Step&& step) -> decltype(step())
{
  try
  {
    return step();
  }
  catch (const PipelineFailure&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    throw PipelineFailure(code, e.what());
  }
}

} // namespace slicemesh::cli

#endif

// A file being written that must not outlive a run stopped part way by a signal.
#ifndef RemovedOnSignal_h
#define RemovedOnSignal_h

#include <string>

namespace slicemesh
{

/** While it lives, `path` is removed if the process is stopped by SIGTERM, SIGINT or SIGHUP (a batch
 *  scheduler's time limit, Ctrl-C, a closed terminal), and the signal then takes its usual course.
 *  For the temporary file a writer renames into place once it is complete: without it, a run stopped
 *  while writing left that hidden file beside the output. The handlers are installed only where the
 *  process has none of its own for those signals (SliceMesh loaded into another program keeps
 *  that program's). Any number of files at once (a run of one mesh per label holds one for each
 *  label until all are written). SIGKILL cannot be caught: a run killed so can still leave the file. */
class RemovedOnSignal
{
public:
  explicit RemovedOnSignal(const std::string& path);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

private:
  int m_Slot = -1; ///< its place in the tables the handler reads, counted across them; -1: not watched
};

} // namespace slicemesh

#endif

// An output file written whole beside its place and moved there only once it is complete.
#ifndef FileReplacement_h
#define FileReplacement_h

#include "RemovedOnSignal.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace slicemesh
{

/** Where writing to `path` puts the file: `path` itself, or, where `path` is a symbolic link, the
 *  file at the end of its links (made absolute), so that the link stays a link and the file it names
 *  is the one replaced, as a shell's redirection or a copy would do. A link whose file does not
 *  exist yet names the file to create. Throws Error if the links cannot be followed (a loop). */
std::filesystem::path writtenPath(const std::filesystem::path& path);

/** writtenPath(path), checked before anything is written: throws Error ("cannot write <what>
 *  '<path>': ...") if the links cannot be followed, the folder of the place does not exist, or the
 *  place is a folder. */
std::filesystem::path writablePlace(const std::string& path, const std::string& what);

/** An output written to a hidden temporary file in the folder of its place (writtenPath), then
 *  renamed over it (commit): a failed or stopped run leaves whatever was there before untouched and
 *  no half-written file. The temporary keeps the output's extension, for writers that choose the
 *  format by it, and carries the process id, so that two runs writing the same output do not share
 *  it. Until commit, it is removed when this object goes (an exception) or the run is stopped by a
 *  signal (RemovedOnSignal). */
class FileReplacement
{
public:
  /** `what` names the output in messages ("mesh": "cannot write mesh '<path>': ..."). Throws Error
   *  as writablePlace does. */
  FileReplacement(const std::string& path, const std::string& what);
  ~FileReplacement();
  FileReplacement(const FileReplacement&) = delete;
  FileReplacement& operator=(const FileReplacement&) = delete;

  /** The file to write. */
  const std::string& temporary() const { return m_Temporary; }

  /** The file it replaces: writablePlace(path). */
  const std::filesystem::path& target() const { return m_Target; }

  /** The temporary file moved into place, with the permission bits of the file it replaces (read,
   *  write and execute; not set-user-ID and the like, nor the owner); throws Error (the temporary
   *  removed) if it cannot be. */
  void commit();

private:
  std::string m_Failure;          ///< "cannot write <what> '<path>'", as the user named it
  std::filesystem::path m_Target; ///< writablePlace(path)
  std::string m_Temporary;
  RemovedOnSignal m_RemovedIfStopped;
  bool m_Committed = false;
};

/** Several outputs moved into place together, in order, or none of them: the meshes of a run of one
 *  mesh per label or ROI and the model they make. `files` are written and not yet committed; an
 *  empty entry is passed over. Each earlier file at their places is kept by a second name beside it
 *  (a hard link: no copy) until all are in place, so that a rename failing part way puts back those
 *  it already replaced (and removes those that were new) and throws that rename's Error; the
 *  temporaries go with their replacements. On a file system without hard links an earlier file
 *  replaced before such a failure cannot be put back. */
void commitTogether(const std::vector<std::unique_ptr<FileReplacement>>& files);

} // namespace slicemesh

#endif

#include "FileReplacement.h"

#include "Core/Lowercase.h"
#include "Core/SliceMeshTypes.h"

#include <cstdio>
#include <system_error>
#include <unistd.h>

namespace slicemesh
{
namespace fs = std::filesystem;

namespace
{

/** "cannot write <what> '<path>'", the start of every message about an output. */
std::string cannotWrite(const std::string& what, const std::string& path)
{
  return "cannot write " + what + " '" + path + "'";
}

/** The folder a file is in ("." for a bare name). */
fs::path folderOf(const fs::path& file)
{
  return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

/** ".<stem>.<kind>-<pid><extension>" beside the target ("partial": the file being written), the
 *  extension in lower case: VTK's PLY writer appends ".ply" to a name that does not end in it, and
 *  would write somewhere else. The stem is cut to 200 bytes: a name of 241 to 255 bytes is a valid
 *  target, but its temporary went past the file system's 255 and failed once the meshing was done. */
std::string temporaryBeside(const fs::path& target, const std::string& kind = "partial")
{
  constexpr std::size_t longestStem = 200;
  std::string stem = target.stem().string();
  if (stem.size() > longestStem)
  {
    std::size_t cut = longestStem;
    while (cut > 0 && (static_cast<unsigned char>(stem[cut]) & 0xC0) == 0x80) // not inside a UTF-8 character
      --cut;
    stem.resize(cut);
  }
  return (folderOf(target) / ("." + stem + "." + kind + "-" + std::to_string(::getpid()) +
                                 lowercase(target.extension().string())))
    .string();
}

} // namespace

fs::path writtenPath(const fs::path& path)
{
  // Followed link by link rather than by fs::canonical, which fails on a link to a file not yet there.
  constexpr int mostLinks = 40; // the kernel's own limit (ELOOP)
  fs::path at = path;
  std::error_code ec;
  for (int links = 0; fs::is_symlink(fs::symlink_status(at, ec)); ++links)
  {
    if (links == mostLinks)
      throw Error("too many levels of symbolic links");
    const fs::path to = fs::read_symlink(at, ec);
    if (ec)
      throw Error("cannot read the symbolic link '" + at.string() + "': " + ec.message());
    at = to.is_absolute() ? to : at.parent_path() / to;
  }
  return at;
}

fs::path writablePlace(const std::string& path, const std::string& what)
{
  const std::string failure = cannotWrite(what, path);
  fs::path target;
  try
  {
    target = writtenPath(path);
  }
  catch (const Error& e)
  {
    throw Error(failure + ": " + e.what());
  }
  const fs::path folder = folderOf(target);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw Error(failure + ": folder '" + folder.string() + "' does not exist");
  if (fs::is_directory(target, ec))
    throw Error(failure + ": it is a folder");
  // Said before any work: the write at the end would fail on it.
  constexpr std::size_t longestName = 255; // bytes, as Linux file systems allow
  if (target.filename().string().size() > longestName)
    throw Error(failure + ": its name is " + std::to_string(target.filename().string().size()) +
                " bytes long; the file system allows " + std::to_string(longestName));
  return target;
}

FileReplacement::FileReplacement(const std::string& path, const std::string& what)
  : m_Failure(cannotWrite(what, path))
  , m_Target(writablePlace(path, what))
  , m_Temporary(temporaryBeside(m_Target))
  , m_RemovedIfStopped(m_Temporary)
{
}

FileReplacement::~FileReplacement()
{
  if (!m_Committed)
  {
    std::error_code ignored;
    fs::remove(m_Temporary, ignored);
  }
}

void FileReplacement::commit()
{
  // The replaced file's permission bits carry over: a mesh kept private (0600) is not made readable
  // by all through the temporary's umask default. A file system without them may refuse: no matter.
  std::error_code noEarlier;
  const fs::file_status earlier = fs::status(m_Target, noEarlier);
  if (!noEarlier && fs::is_regular_file(earlier))
  {
    std::error_code ignored;
    fs::permissions(m_Temporary, earlier.permissions() & fs::perms::all, fs::perm_options::replace, ignored);
  }
  // std::rename: one rename(2), atomic within the folder.
  if (std::rename(m_Temporary.c_str(), m_Target.c_str()) != 0)
    throw Error(m_Failure + ": renaming the finished file into place failed");
  m_Committed = true;
}

namespace
{

/** An earlier file at a replacement's place, kept by a second name while a group is committed. */
struct KeptEarlier
{
  fs::path target;
  bool existed = false;
  std::string keptAs; ///< the hard link to it; empty where there was none or none could be made
  std::unique_ptr<RemovedOnSignal> removedIfStopped;
};

} // namespace

void commitTogether(const std::vector<std::unique_ptr<FileReplacement>>& files)
{
  std::vector<KeptEarlier> earlier;
  for (const std::unique_ptr<FileReplacement>& file : files)
  {
    if (!file)
      continue;
    KeptEarlier kept;
    kept.target = file->target();
    std::error_code ignored;
    kept.existed = fs::exists(kept.target, ignored);
    const std::string link = temporaryBeside(kept.target, "earlier");
    if (kept.existed && ::link(kept.target.c_str(), link.c_str()) == 0)
    {
      kept.keptAs = link;
      kept.removedIfStopped = std::make_unique<RemovedOnSignal>(link);
    }
    earlier.push_back(std::move(kept));
  }
  const auto removeKeptLinks = [&earlier]
  {
    for (const KeptEarlier& kept : earlier)
    {
      std::error_code ignored;
      if (!kept.keptAs.empty())
        fs::remove(kept.keptAs, ignored);
    }
  };
  std::size_t placed = 0;
  try
  {
    for (const std::unique_ptr<FileReplacement>& file : files)
      if (file)
      {
        file->commit();
        ++placed;
      }
  }
  catch (const Error&)
  {
    // Those already in place are undone: the earlier file back, or the new one gone where there was none.
    for (std::size_t n = 0; n < placed; ++n)
    {
      std::error_code ignored;
      if (!earlier[n].keptAs.empty() && std::rename(earlier[n].keptAs.c_str(), earlier[n].target.c_str()) == 0)
        earlier[n].keptAs.clear();
      else if (!earlier[n].existed)
        fs::remove(earlier[n].target, ignored);
    }
    removeKeptLinks();
    throw;
  }
  removeKeptLinks();
}

} // namespace slicemesh

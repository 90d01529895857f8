// FileReplacement: an output replaces what was at its place only once complete, and a symbolic link
// at that place is written through (the link kept, the file it names replaced).
#include "FileReplacement.h"

#include "Core/SliceMeshTypes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace fs = std::filesystem;

namespace slicemesh
{
namespace
{

fs::path freshFolder(const std::string& name)
{
  const fs::path folder = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / "FileReplacement" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string fileText(const fs::path& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write(const FileReplacement& file, const std::string& text)
{
  std::ofstream(file.temporary()) << text;
}

/** The names in `folder`, hidden ones too. */
std::size_t entriesIn(const fs::path& folder)
{
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(FileReplacement, ReplacesTheFileOnlyOnCommit)
{
  const fs::path folder = freshFolder("commit");
  const fs::path path = folder / "out.json";
  std::ofstream(path) << "before";
  {
    FileReplacement file(path.string(), "report");
    EXPECT_EQ(fs::path(file.temporary()).parent_path(), folder);
    EXPECT_EQ(fs::path(file.temporary()).extension(), ".json") << "writers choose the format by it";
    write(file, "after");
    EXPECT_EQ(fileText(path), "before");
    file.commit();
  }
  EXPECT_EQ(fileText(path), "after");
  EXPECT_EQ(entriesIn(folder), 1u) << "no temporary left";
}

TEST(FileReplacement, AnUncommittedFileLeavesThePlaceAsItWas)
{
  const fs::path folder = freshFolder("abandoned");
  const fs::path path = folder / "out.vtp";
  std::ofstream(path) << "precious";
  {
    FileReplacement file(path.string(), "mesh");
    write(file, "half");
  }
  EXPECT_EQ(fileText(path), "precious");
  EXPECT_EQ(entriesIn(folder), 1u);
}

TEST(FileReplacement, WritesThroughASymbolicLink)
{
  const fs::path folder = freshFolder("link");
  fs::create_directories(folder / "results");
  const fs::path file = folder / "results" / "mesh.vtp";
  std::ofstream(file) << "old";
  const fs::path link = folder / "latest.vtp";
  fs::create_symlink(fs::path("results") / "mesh.vtp", link); // relative to the link's folder
  {
    FileReplacement replacement(link.string(), "mesh");
    EXPECT_EQ(fs::path(replacement.temporary()).parent_path(), folder / "results")
      << "beside the file, so that the rename stays in one folder";
    write(replacement, "new");
    replacement.commit();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(fs::read_symlink(link), fs::path("results") / "mesh.vtp");
  EXPECT_EQ(fileText(file), "new");
  EXPECT_EQ(entriesIn(folder / "results"), 1u);
}

TEST(FileReplacement, FollowsAChainOfLinksAndCreatesTheFileALinkNames)
{
  const fs::path folder = freshFolder("chain");
  const fs::path file = folder / "mesh.stl";
  fs::create_symlink(file, folder / "b.stl"); // absolute, to a file not there yet
  fs::create_symlink("b.stl", folder / "a.stl");
  EXPECT_EQ(writtenPath(folder / "a.stl"), file);
  FileReplacement replacement((folder / "a.stl").string(), "mesh");
  write(replacement, "solid");
  replacement.commit();
  EXPECT_EQ(fileText(file), "solid");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder / "a.stl")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder / "b.stl")));
}

TEST(FileReplacement, PlacesThatCannotBeWrittenAreRefusedBeforeWriting)
{
  const fs::path folder = freshFolder("refused");
  fs::create_symlink("loop-b.vtp", folder / "loop-a.vtp");
  fs::create_symlink("loop-a.vtp", folder / "loop-b.vtp");
  fs::create_directories(folder / "a-folder");
  fs::create_symlink("a-folder", folder / "to-folder.vtp");
  fs::create_symlink(folder / "missing" / "mesh.vtp", folder / "to-missing.vtp");
  for (const std::string name : { "loop-a.vtp", "a-folder", "to-folder.vtp", "to-missing.vtp" })
  {
    const std::string path = (folder / name).string();
    try
    {
      FileReplacement file(path, "mesh");
      ADD_FAILURE() << name << ": accepted";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("cannot write mesh '" + path + "': ", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(entriesIn(folder), 5u) << "nothing created";
}

/** FileReplacements of the named files in `folder`, each written with "<name> new". */
std::vector<std::unique_ptr<FileReplacement>> writtenReplacements(const fs::path& folder,
                                                                  const std::vector<std::string>& names)
{
  std::vector<std::unique_ptr<FileReplacement>> files;
  for (const std::string& name : names)
  {
    files.push_back(std::make_unique<FileReplacement>((folder / name).string(), "mesh"));
    write(*files.back(), name + " new");
  }
  files.insert(files.begin() + 1, nullptr); // an empty slot, passed over
  return files;
}

TEST(FileReplacement, AReplacedFileKeepsItsPermissions)
{
  // The temporary is made with the umask's default (0644 as a rule): a private mesh stays private.
  const fs::path folder = freshFolder("permissions");
  const auto permissionsOf = [](const fs::path& path) { return fs::status(path).permissions() & fs::perms::all; };
  std::ofstream(folder / "private.vtp") << "before";
  fs::permissions(folder / "private.vtp", fs::perms::owner_read | fs::perms::owner_write);
  {
    FileReplacement file((folder / "private.vtp").string(), "mesh");
    write(file, "after");
    file.commit();
  }
  EXPECT_EQ(fileText(folder / "private.vtp"), "after");
  EXPECT_EQ(permissionsOf(folder / "private.vtp"), fs::perms::owner_read | fs::perms::owner_write);

  // Committed together, the same; a new file has the permissions any new file gets.
  std::ofstream(folder / "group.vtp") << "before";
  const fs::perms group = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
  fs::permissions(folder / "group.vtp", group);
  std::ofstream(folder / "plain.txt") << "a new file";
  {
    const auto files = writtenReplacements(folder, { "group.vtp", "new.vtp" });
    commitTogether(files);
  }
  EXPECT_EQ(fileText(folder / "group.vtp"), "group.vtp new");
  EXPECT_EQ(permissionsOf(folder / "group.vtp"), group);
  EXPECT_EQ(permissionsOf(folder / "new.vtp"), permissionsOf(folder / "plain.txt"));
}

TEST(FileReplacement, FilesCommittedTogetherReplaceTheirsAllAtOnce)
{
  const fs::path folder = freshFolder("together");
  std::ofstream(folder / "a.vtp") << "a old";
  {
    const auto files = writtenReplacements(folder, { "a.vtp", "b.vtp" });
    EXPECT_EQ(fileText(folder / "a.vtp"), "a old") << "untouched until committed";
    EXPECT_FALSE(fs::exists(folder / "b.vtp"));
    commitTogether(files);
  }
  EXPECT_EQ(fileText(folder / "a.vtp"), "a.vtp new");
  EXPECT_EQ(fileText(folder / "b.vtp"), "b.vtp new");
  EXPECT_EQ(entriesIn(folder), 2u) << "no temporary or earlier file left";
}

TEST(FileReplacement, ARenameFailingPartWayThroughACommitPutsBackThoseBeforeIt)
{
  // c's place turns into a folder after its file is written: its rename fails once a and b are in
  // place; a's earlier file comes back and b, new, goes.
  const fs::path folder = freshFolder("together-undone");
  std::ofstream(folder / "a.vtp") << "a old";
  std::ofstream(folder / "c.vtp") << "c old";
  {
    const auto files = writtenReplacements(folder, { "a.vtp", "b.vtp", "c.vtp" });
    fs::remove(folder / "c.vtp");
    fs::create_directories(folder / "c.vtp" / "inside");
    EXPECT_THROW(commitTogether(files), Error);
  }
  EXPECT_EQ(fileText(folder / "a.vtp"), "a old");
  EXPECT_FALSE(fs::exists(folder / "b.vtp"));
  EXPECT_TRUE(fs::is_directory(folder / "c.vtp"));
  EXPECT_EQ(entriesIn(folder), 2u) << "no temporary or earlier file left";
}

} // namespace
} // namespace slicemesh

// The fixture of the image module's tests that write the files they read: a fresh folder under the
// system's temporary folder for each test, removed after it.
#ifndef TemporaryFolderTest_h
#define TemporaryFolderTest_h

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace slicemesh::testing
{

class TemporaryFolderTest : public ::testing::Test
{
protected:
  /** The folder is named `prefix` and a random number ("slicemesh-reader-1234"), so that test runs
   *  side by side do not share it. */
  explicit TemporaryFolderTest(std::string prefix)
    : m_Prefix(std::move(prefix))
  {
  }
  void SetUp() override
  {
    std::random_device seed;
    m_Folder = std::filesystem::temp_directory_path() / (m_Prefix + std::to_string(seed()));
    std::filesystem::create_directories(m_Folder);
  }
  void TearDown() override { std::filesystem::remove_all(m_Folder); }

  const std::filesystem::path& folder() const { return m_Folder; }
  std::string path(const std::string& name) const { return (m_Folder / name).string(); }

private:
  std::string m_Prefix;
  std::filesystem::path m_Folder;
};

} // namespace slicemesh::testing

#endif

#include "Core/DefaultInitAllocator.h"
#include "Core/HugePages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace slicemesh
{
namespace
{

#if defined(__linux__) && defined(MADV_HUGEPAGE)
/** The kernel's flags of the mapping that holds `address` (VmFlags of /proc/self/smaps), or "" if
 *  none is found. */
std::string mappingFlags(std::uintptr_t address)
{
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t low = 0, high = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> low >> dash >> high && dash == '-' && line.find(':') > line.find(' '))
    {
      inside = low <= address && address < high;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return {};
}

bool markedForHugePages(std::uintptr_t address)
{
  std::istringstream flags(mappingFlags(address));
  std::string flag;
  while (flags >> flag)
    if (flag == "hg")
      return true;
  return false;
}

TEST(HugePages, TheAlignedPagesOfALargeBlockAreMarkedAndASmallBlockIsLeftAlone)
{
  constexpr std::size_t hugePage = std::size_t(2) << 20;
  constexpr std::size_t size = 5 * hugePage;
  void* block = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(block, MAP_FAILED);
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t firstWhole = (at + hugePage - 1) & ~(std::uintptr_t(hugePage) - 1);
  ASSERT_FALSE(markedForHugePages(firstWhole)) << "a fresh mapping is not marked";

  // A small block inside the mapping (one huge page's worth) is left alone.
  adviseHugePages(reinterpret_cast<void*>(firstWhole), hugePage);
  EXPECT_FALSE(markedForHugePages(firstWhole));

  // A kernel without transparent huge pages (or a sandbox's) refuses the advice: asked directly on
  // a mapping of its own, the kernel says which it does, and nothing is marked where it refuses.
  void* probe = mmap(nullptr, 2 * hugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(probe, MAP_FAILED);
  const bool kernelHasThem = madvise(probe, 2 * hugePage, MADV_HUGEPAGE) == 0;
  munmap(probe, 2 * hugePage);
  adviseHugePages(block, size);
  EXPECT_EQ(markedForHugePages(firstWhole), kernelHasThem);
  EXPECT_EQ(markedForHugePages(firstWhole + 3 * hugePage), kernelHasThem);
  if (firstWhole > at)
    EXPECT_FALSE(markedForHugePages(at)) << "the part before the first whole huge page is not advised";
  munmap(block, size);
}
#endif

struct WithDefault
{
  int value = 7;
};

TEST(DefaultInitAllocator, ElementsWithTheirOwnInitializationKeepItAndGivenValuesAreKept)
{
  std::vector<WithDefault, DefaultInitAllocator<WithDefault>> initialized(1000);
  for (const WithDefault& w : initialized)
    ASSERT_EQ(w.value, 7);
  std::vector<int, DefaultInitAllocator<int>> filled(1000, 3);
  filled.resize(2000, 5);
  filled.push_back(9);
  EXPECT_EQ(filled[999], 3);
  EXPECT_EQ(filled[1999], 5);
  EXPECT_EQ(filled.back(), 9);
  std::vector<int, DefaultInitAllocator<int>> copy = filled;
  EXPECT_EQ(copy, filled);
}

} // namespace
} // namespace slicemesh

// Advice to the kernel that a large block of memory be backed by transparent huge pages (2 MB)
// where it leaves that to the program (Debian's default "madvise" setting). A run fills and drops
// arrays of tens of megabytes stage after stage; each 4 KB page of them costs a fault on first touch
// and a TLB entry after, and on a virtual machine of two cores those faults were a tenth of a large
// volume's run. A huge page is one fault and one entry.
#ifndef HugePages_h
#define HugePages_h

#include <cerrno>
#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace slicemesh
{

/** Marks the whole 2 MB pages inside the `size` bytes at `p` for huge pages. Blocks under two such
 *  pages are left alone: most of theirs would fall outside an aligned page. Advice only: where the
 *  kernel refuses it (or has no such pages), nothing changes. */
inline void adviseHugePages(void* p, std::size_t size) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t hugePage = std::uintptr_t(2) << 20;
  if (!p || size < 2 * hugePage)
    return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + hugePage - 1) & ~(hugePage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + size) & ~(hugePage - 1);
  if (end > begin)
  {
    const int savedErrno = errno; // advice from within an allocation must not leave an error behind
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    errno = savedErrno;
  }
#else
  (void)p;
  (void)size;
#endif
}

} // namespace slicemesh

#endif

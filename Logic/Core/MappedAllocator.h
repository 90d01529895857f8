// An allocator for a few large arrays that live through one stage and then go: their memory, from a
// quarter of a megabyte up, comes straight from the kernel's page mappings and goes back to it when
// they are freed (smaller ones, of small meshes by the thousand, through malloc). Through malloc,
// blocks of a few megabytes freed mid-run stayed in the process (glibc raises its threshold for
// mapping large blocks as such blocks are freed, and the heap it then uses keeps its free pages):
// the 128³ sphere's peak resident memory rose from 60 to 66 MB, past the flying-edges pipeline's.
#ifndef MappedAllocator_h
#define MappedAllocator_h

#include "Core/HugePages.h"

#include <cstddef>
#include <memory>
#include <new>

#if defined(__unix__)
#include <sys/mman.h>
#endif

namespace slicemesh
{

template <typename T>
struct MappedAllocator
{
  using value_type = T;

  static bool mapped(std::size_t n) { return n * sizeof(T) >= (std::size_t(1) << 18); }

  MappedAllocator() = default;
  template <typename U>
  MappedAllocator(const MappedAllocator<U>&) noexcept
  {
  }

  T* allocate(std::size_t n)
  {
    if (n > static_cast<std::size_t>(-1) / sizeof(T))
      throw std::bad_array_new_length();
#if defined(__unix__)
    if (mapped(n))
    {
      void* p = mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED)
        throw std::bad_alloc();
      adviseHugePages(p, n * sizeof(T));
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) noexcept
  {
#if defined(__unix__)
    if (mapped(n))
    {
      munmap(p, n * sizeof(T));
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <typename U>
  bool operator==(const MappedAllocator<U>&) const noexcept
  {
    return true;
  }
  template <typename U>
  bool operator!=(const MappedAllocator<U>&) const noexcept
  {
    return false;
  }
};

} // namespace slicemesh

#endif

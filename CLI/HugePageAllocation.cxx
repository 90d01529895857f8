// The executable's operator new: malloc, as the default one, but a large block is marked for
// transparent huge pages (Core/HugePages.h): a surface's points, its edge table, the smoothing's
// copies, a volume's voxels. Only the executable's: the libraries, their tests and a process that
// loads them keep their own allocation. Not in a build with AddressSanitizer, whose own operator new
// checks that each block is freed by the delete that matches it.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SLICEMESH_ADDRESS_SANITIZER
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SLICEMESH_ADDRESS_SANITIZER
#endif

#if !defined(SLICEMESH_ADDRESS_SANITIZER)
#include "Core/HugePages.h"

#include <cstddef>
#include <cstdlib>
#include <new>

namespace
{

void* allocate(std::size_t size) noexcept
{
  void* p = std::malloc(size == 0 ? 1 : size);
  slicemesh::adviseHugePages(p, size);
  return p;
}

} // namespace

void* operator new(std::size_t size)
{
  if (void* p = allocate(size))
    return p;
  throw std::bad_alloc();
}

void* operator new[](std::size_t size)
{
  return operator new(size);
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  return allocate(size);
}

void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
  return allocate(size);
}

void operator delete(void* p) noexcept
{
  std::free(p);
}

void operator delete[](void* p) noexcept
{
  std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}

void operator delete(void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}

void operator delete[](void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}

#endif

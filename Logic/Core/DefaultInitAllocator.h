// An allocator whose containers leave new elements of a trivial type uninitialized (default
// initialization) where std::allocator zeroes them: for large arrays that a parallel pass fills
// right after they are sized. Zeroed on one thread first, such an array's pages were all touched
// there while the other cores waited; left alone, each page is first touched by the thread that
// fills it.
#ifndef DefaultInitAllocator_h
#define DefaultInitAllocator_h

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace slicemesh
{

template <typename T, typename Base = std::allocator<T>>
struct DefaultInitAllocator : Base
{
  using Traits = std::allocator_traits<Base>;

  template <typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };

  using Base::Base;

  /** No arguments: default initialization (a trivial type is left as the memory holds it). */
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U;
  }

  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

} // namespace slicemesh

#endif

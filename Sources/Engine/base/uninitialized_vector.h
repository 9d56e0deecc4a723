#pragma once
// A std::vector whose resize leaves new elements of trivial types uninitialised, for
// large arrays that parallel loops then fill. The system zeroes a page where it is
// first touched; a std::vector's own zeroing touches every page on one core first (a
// 4097^2 grid's horizon map: 1 GB, 2 s of one core while the other waited). Large ones
// take huge pages (large_arrays.h).

#include "base/large_arrays.h"

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace terralux
{
template <typename T>
struct DefaultInitAllocator : LargeArrayAllocator<T>
{
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  /// Default-initialised: nothing written for a trivial type.
  template <typename U>
  void construct(U* place) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(place)) U;
  }
  template <typename U, typename... Args>
  void construct(U* place, Args&&... args)
  {
    ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
  }
};

/// resize() leaves trivial elements unset: every one must be written before it is read.
template <typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;
} // namespace terralux

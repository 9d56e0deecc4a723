#pragma once
// Memory for the solve's large arrays (horizon maps, the posts' skies, the terrain's
// posts, the outputs), advised to the kernel as transparent huge pages where it allows
// them (Linux with THP in "madvise" mode, Debian's default). A large array's pages are
// faulted in on first touch; at 4 KiB a page, the 1025^2 benchmark's 240 MB took 56,000
// faults, about a tenth of its CPU time in a virtual machine; at 2 MiB they are a few
// hundred (docs/tuning.md).

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace terralux
{
namespace large_arrays
{
/// Arrays from this size on (bytes) take huge pages; smaller ones the heap's own.
constexpr std::size_t threshold = std::size_t{ 4 } << 20;
constexpr std::size_t hugePage = std::size_t{ 2 } << 20;

/// `bytes` aligned to a huge page and advised as huge pages; std::free releases it.
inline void* allocate(std::size_t bytes)
{
  void* memory = nullptr;
  if (posix_memalign(&memory, hugePage, bytes) != 0)
    throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(memory, bytes, MADV_HUGEPAGE); // advice only: where refused, 4 KiB pages as before
#endif
  return memory;
}
} // namespace large_arrays

/// The heap's memory for small arrays, large_arrays::allocate's from its threshold on.
/// No rebind member: std::allocator_traits rebinds it (and allocators built on it) by
/// their template argument.
template <typename T>
struct LargeArrayAllocator
{
  using value_type = T;
  LargeArrayAllocator() = default;
  template <typename U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept
  {
  }
  T* allocate(std::size_t n)
  {
    if (n * sizeof(T) < large_arrays::threshold)
      return static_cast<T*>(::operator new(n * sizeof(T)));
    return static_cast<T*>(large_arrays::allocate(n * sizeof(T)));
  }
  void deallocate(T* memory, std::size_t n) noexcept
  {
    if (n * sizeof(T) < large_arrays::threshold)
      ::operator delete(memory);
    else
      std::free(memory);
  }
};
template <typename T, typename U>
bool operator==(const LargeArrayAllocator<T>&, const LargeArrayAllocator<U>&) noexcept
{
  return true;
}
template <typename T, typename U>
bool operator!=(const LargeArrayAllocator<T>&, const LargeArrayAllocator<U>&) noexcept
{
  return false;
}

/// A std::vector of large_arrays memory.
template <typename T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;
} // namespace terralux

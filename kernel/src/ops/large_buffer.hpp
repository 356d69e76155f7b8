#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace nome {

// An allocator for big arrays that are written right after they are allocated (refinement levels):
// elements start uninitialized (no zero-fill pass), and blocks of 2 MB or more are aligned to 2 MB and
// marked for transparent huge pages, which cuts the page faults of fresh memory (a quarter to a half of
// the refinement time on these machines) about 500-fold.
template <class T>
struct LargeBufferAllocator {
  using value_type = T;
  static constexpr std::size_t huge_page = std::size_t(2) << 20;

  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_page) return static_cast<T*>(::operator new(bytes));
    const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
    void* p = ::operator new(rounded, std::align_val_t(huge_page));
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without huge pages it still works
    return static_cast<T*>(p);
  }
  // Unsized deletes: clang-14 (the fuzz build) has no sized deallocation by default.
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < huge_page)
      ::operator delete(p);
    else
      ::operator delete(p, std::align_val_t(huge_page));
  }
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialization: trivial types stay unwritten
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LargeBuffer = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace nome

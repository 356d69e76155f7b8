#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <new>
#include <type_traits>
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

// Reserves room for n elements in a plain std::vector (a Mesh's arrays, which the public API keeps as
// std::vector) that is about to be filled, the block marked for transparent huge pages before its first
// touch: the same cut in page faults as LargeBuffer, where the type cannot change.
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t n) {
  constexpr std::size_t page = 4096;
  if (n * sizeof(T) < LargeBufferAllocator<T>::huge_page || v.capacity() >= n) return;
  v.reserve(n);
  const auto start = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = start / page * page;
  madvise(reinterpret_cast<void*>(first), start + n * sizeof(T) - first, MADV_HUGEPAGE);  // advice only
}

// New elements are value-initialized in place (copying one value into millions of records made GCC stage
// each copy through the stack: a store-forwarding stall per element).
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n) {
  reserve_on_huge_pages(v, n);
  v.resize(n);
}

template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n, const std::type_identity_t<T>& value) {
  reserve_on_huge_pages(v, n);
  v.resize(n, value);
}

template <class T, class Range>
void assign_on_huge_pages(std::vector<T>& v, const Range& range) {
  reserve_on_huge_pages(v, std::size(range));
  v.assign(std::begin(range), std::end(range));
}

}  // namespace nome

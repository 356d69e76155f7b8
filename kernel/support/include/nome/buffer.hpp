#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace nome {

// Blocks for big arrays; of 2 MB or more they come from mmap, aligned to 2 MB, for the cache of freed
// blocks below (not on huge pages: buffer.cpp says why).
void* allocate_buffer(std::size_t bytes);
void free_buffer(void* block, std::size_t bytes) noexcept;
// Keeps freed blocks of 2 MB or more, up to `limit` bytes in all, for later allocations of any size: a
// smaller one takes part of a block, a larger one the kept blocks' pages moved together and fresh ones
// for the rest (0, the default, keeps none; keep_freed_memory() sets it for a program).
void keep_freed_buffers(std::size_t limit);

// The allocator of Buffer: new elements are default-initialized, so arrays of trivial types are not
// zero-filled before the code that sized them writes every element (a whole extra pass over the memory
// for a mesh of millions of faces).
template <class T>
struct BufferAllocator {
  using value_type = T;

  BufferAllocator() = default;
  template <class U>
  BufferAllocator(const BufferAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) { return static_cast<T*>(allocate_buffer(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { free_buffer(p, n * sizeof(T)); }
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialization: trivial types stay unwritten
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const BufferAllocator<U>&) const noexcept {
    return true;
  }
};

// A mesh's arrays: a std::vector whose resize(n) leaves trivial elements unwritten (resize(n, value)
// and assignments write them as usual).
template <class T>
using Buffer = std::vector<T, BufferAllocator<T>>;

// Sizes `b` to n elements for code that then writes every one of them: the old contents are dropped
// rather than copied if the block has to grow, and a block that is large enough is kept (no fresh pages).
template <class T>
void resize_for_overwrite(Buffer<T>& b, std::size_t n) {
  b.clear();
  b.resize(n);
}

}  // namespace nome

#include "nome/mesh/buffer.hpp"

#include <sys/mman.h>

namespace nome {
namespace {

constexpr std::size_t huge_page = std::size_t(2) << 20;

}  // namespace

void* allocate_buffer(std::size_t bytes) {
  if (bytes < huge_page) return ::operator new(bytes);
  const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
  void* block = ::operator new(rounded, std::align_val_t(huge_page));
  madvise(block, rounded, MADV_HUGEPAGE);  // advice only: without huge pages it still works
  return block;
}

// Unsized deletes: clang-14 (the fuzz build) has no sized deallocation by default.
void free_buffer(void* block, std::size_t bytes) noexcept {
  if (bytes < huge_page)
    ::operator delete(block);
  else
    ::operator delete(block, std::align_val_t(huge_page));
}

}  // namespace nome

#include "nome/mesh/buffer.hpp"

#include <sys/mman.h>

#include <map>
#include <mutex>

namespace nome {
namespace {

constexpr std::size_t huge_page = std::size_t(2) << 20;

// Freed big blocks kept for the next allocation of the same rounded size, once a program asked for it
// (keep_freed_buffers): glibc hands 2 MB-aligned blocks back out as fresh pages, so without this every
// mesh of a few hundred thousand faces faulted in all its memory again (three quarters of a sweep's build).
struct BlockCache {
  std::mutex mutex;
  std::multimap<std::size_t, void*> blocks;  // rounded size -> block
  std::size_t bytes = 0, limit = 0;

  ~BlockCache() {
    for (const auto& [size, block] : blocks) ::operator delete(block, std::align_val_t(huge_page));
  }
  void* take(std::size_t rounded) {
    const std::lock_guard lock(mutex);
    const auto it = blocks.find(rounded);
    if (it == blocks.end()) return nullptr;
    void* block = it->second;
    blocks.erase(it);
    bytes -= rounded;
    return block;
  }
  bool keep(void* block, std::size_t rounded) {
    const std::lock_guard lock(mutex);
    if (bytes + rounded > limit) return false;
    blocks.emplace(rounded, block);
    bytes += rounded;
    return true;
  }
};

BlockCache& block_cache() {
  static BlockCache cache;
  return cache;
}

std::size_t rounded_size(std::size_t bytes) {
  return (bytes + huge_page - 1) / huge_page * huge_page;
}

}  // namespace

void keep_freed_buffers(std::size_t limit) {
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  cache.limit = limit;
  while (cache.bytes > limit) {
    const auto it = cache.blocks.begin();
    ::operator delete(it->second, std::align_val_t(huge_page));
    cache.bytes -= it->first;
    cache.blocks.erase(it);
  }
}

void* allocate_buffer(std::size_t bytes) {
  if (bytes < huge_page) return ::operator new(bytes);
  const std::size_t rounded = rounded_size(bytes);
  if (void* kept = block_cache().take(rounded)) return kept;
  void* block = ::operator new(rounded, std::align_val_t(huge_page));
  madvise(block, rounded, MADV_HUGEPAGE);  // advice only: without huge pages it still works
  return block;
}

// Unsized deletes: clang-14 (the fuzz build) has no sized deallocation by default.
void free_buffer(void* block, std::size_t bytes) noexcept {
  if (bytes < huge_page) {
    ::operator delete(block);
    return;
  }
  if (!block_cache().keep(block, rounded_size(bytes))) ::operator delete(block, std::align_val_t(huge_page));
}

}  // namespace nome

#include "nome/buffer.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <mutex>
#include <set>

namespace nome {
namespace {

// Big blocks are whole units of 2 MB, aligned to one: kept ranges split and join in pieces any block can
// use, and where the system puts all memory on huge pages (THP "always") a block holds whole ones.
constexpr std::size_t block_unit = std::size_t(2) << 20;

std::size_t rounded_size(std::size_t bytes) {
  return (bytes + block_unit - 1) / block_unit * block_unit;
}

// Big blocks come straight from mmap, so that kept memory can be cut, joined and moved to
// where a new block needs it (munmap and mremap work on pages, not on what malloc handed out).
// They are not marked for transparent huge pages: on virtual machines that hand free memory back to the
// host, a fresh huge page is cut from memory the host must give again, several times slower to fault in
// than small pages; huge pages pay off only for memory used again, which the kept blocks below give.
char* map_block(std::size_t rounded) {
  const std::size_t mapped = rounded + block_unit;
  void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  char* start = static_cast<char*>(raw);
  char* block = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(start) + block_unit - 1) &
                                        ~std::uintptr_t(block_unit - 1));
  if (block > start) munmap(start, std::size_t(block - start));
  const std::size_t tail = mapped - std::size_t(block - start) - rounded;
  if (tail > 0) munmap(block + rounded, tail);
  return block;
}

// Freed big blocks kept for later allocations of any size, once a program asked for it
// (keep_freed_buffers). Faulting in never touched pages costs far more than moving warm pages from kept
// blocks; a kept block that only a request of its own size could take would stay resident unused, so a
// request takes the smallest kept range that holds it, or else
// moves kept ranges, largest first, into a fresh block with mremap (the pages move, warm, without a
// copy); what they do not cover stays fresh.
struct BlockCache {
  std::mutex mutex;
  std::map<char*, std::size_t> ranges;               // start -> bytes, none touching another
  std::multimap<std::size_t, char*> ranges_by_size;  // bytes -> start, the same ranges
  // Where one mapping may end and the next begin inside a range (ranges joined, pieces moved together):
  // mremap moves one mapping at a time. More seams than mappings cost only extra calls.
  std::set<char*> seams;
  std::size_t bytes = 0, limit = 0;

  void add(char* start, std::size_t size) {
    ranges.emplace(start, size);
    ranges_by_size.emplace(size, start);
    bytes += size;
  }
  void remove(std::map<char*, std::size_t>::iterator range) {
    auto same_size = ranges_by_size.find(range->second);
    while (same_size->second != range->first) ++same_size;
    ranges_by_size.erase(same_size);
    bytes -= range->second;
    ranges.erase(range);
  }
  // The pages of [start, start + size) no longer ours at this address (moved or unmapped).
  void forget_seams(char* start, std::size_t size) {
    seams.erase(seams.lower_bound(start), seams.lower_bound(start + size));
  }
  // Moves [from, from + size) to `to`, one mapping at a time; false if the system refused (the pages
  // not moved stay where they were, the ones at `to` stay fresh).
  bool move(char* from, std::size_t size, char* to) {
    char* piece = from;
    auto seam = seams.upper_bound(from);
    while (piece < from + size) {
      char* end = from + size;
      if (seam != seams.end() && *seam < end) end = *seam++;
      if (mremap(piece, std::size_t(end - piece), std::size_t(end - piece), MREMAP_MAYMOVE | MREMAP_FIXED,
                 to + (piece - from)) == MAP_FAILED)
        return false;
      if (piece > from) seams.insert(to + (piece - from));
      piece = end;
    }
    forget_seams(from, size);
    return true;
  }
  char* take(std::size_t rounded) {
    const std::lock_guard lock(mutex);
    if (const auto fit = ranges_by_size.lower_bound(rounded); fit != ranges_by_size.end()) {
      char* start = fit->second;
      const std::size_t size = fit->first;
      remove(ranges.find(start));
      if (size > rounded) add(start + rounded, size - rounded);
      return start;
    }
    if (ranges.empty()) return nullptr;
    char* block = map_block(rounded);
    std::size_t filled = 0;
    while (filled < rounded && !ranges_by_size.empty()) {
      const auto largest = std::prev(ranges_by_size.end());
      char* start = largest->second;
      const std::size_t whole = largest->first, size = std::min(whole, rounded - filled);
      remove(ranges.find(start));
      if (whole > size) add(start + size, whole - size);
      if (!move(start, size, block + filled)) {
        unmap(start, size);
        continue;
      }
      seams.insert(block + filled);
      filled += size;
    }
    if (filled < rounded) seams.insert(block + filled);
    return block;
  }
  bool keep(char* start, std::size_t size) {
    const std::lock_guard lock(mutex);
    if (bytes + size > limit) return false;
    const auto next = ranges.lower_bound(start);
    if (next != ranges.begin()) {
      const auto before = std::prev(next);
      if (before->first + before->second == start) {
        seams.insert(start);
        start = before->first;
        size += before->second;
        remove(before);
      }
    }
    if (next != ranges.end() && start + size == next->first) {
      seams.insert(next->first);
      size += next->second;
      remove(next);
    }
    add(start, size);
    return true;
  }
  void unmap(char* start, std::size_t size) {
    munmap(start, size);
    forget_seams(start, size);
  }
  // Unmaps kept ranges, largest first, until at most `kept` bytes remain.
  void shrink_to(std::size_t kept) {
    while (bytes > kept) {
      const auto largest = std::prev(ranges_by_size.end());
      char* start = largest->second;
      const std::size_t size = largest->first;
      remove(ranges.find(start));
      unmap(start, size);
    }
  }
};

BlockCache& block_cache() {
  static BlockCache cache;
  return cache;
}

}  // namespace

void keep_freed_buffers(std::size_t limit) {
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  cache.limit = limit;
  cache.shrink_to(limit);
}

void* allocate_buffer(std::size_t bytes) {
  if (bytes < block_unit) return ::operator new(bytes);
  const std::size_t rounded = rounded_size(bytes);
  if (char* kept = block_cache().take(rounded)) return kept;
  return map_block(rounded);
}

// Unsized deletes: clang-14 (the fuzz build) has no sized deallocation by default.
void free_buffer(void* block, std::size_t bytes) noexcept {
  if (bytes < block_unit) {
    ::operator delete(block);
    return;
  }
  char* start = static_cast<char*>(block);
  const std::size_t rounded = rounded_size(bytes);
  BlockCache& cache = block_cache();
  if (!cache.keep(start, rounded)) {
    const std::lock_guard lock(cache.mutex);
    cache.unmap(start, rounded);
  }
}

}  // namespace nome

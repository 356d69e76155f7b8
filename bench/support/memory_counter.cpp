#include "support/memory_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<std::size_t> live{0}, peak{0}, base{0};
// Each block carries its size in a header of one max_align_t, so that delete knows what it frees.
constexpr std::size_t header = alignof(std::max_align_t);

void count(std::size_t size) {
  const std::size_t now = live.fetch_add(size) + size;
  std::size_t seen = peak.load();
  while (now > seen && !peak.compare_exchange_weak(seen, now)) {
  }
}

void* allocate(std::size_t size) {
  void* raw = std::malloc(size + header);
  if (!raw) return nullptr;
  *static_cast<std::size_t*>(raw) = size;
  count(size);
  return static_cast<char*>(raw) + header;
}

void release(void* p) {
  if (!p) return;
  void* raw = static_cast<char*>(p) - header;
  live.fetch_sub(*static_cast<std::size_t*>(raw));
  std::free(raw);
}

}  // namespace

void* operator new(std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return allocate(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return allocate(size);
}
void operator delete(void* p) noexcept {
  release(p);
}
void operator delete[](void* p) noexcept {
  release(p);
}
void operator delete(void* p, std::size_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  release(p);
}

// Over-aligned blocks (huge-page buffers) carry their size in a header of one alignment unit too, since
// the kernel's allocator frees them with the unsized delete.
void* operator new(std::size_t size, std::align_val_t align) {
  const std::size_t a = std::size_t(align);
  char* raw = static_cast<char*>(std::aligned_alloc(a, a + (size + a - 1) / a * a));
  if (!raw) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(raw) = size;
  count(size);
  return raw + a;
}
void operator delete(void* p, std::align_val_t align) noexcept {
  if (!p) return;
  char* raw = static_cast<char*>(p) - std::size_t(align);
  live.fetch_sub(*reinterpret_cast<std::size_t*>(raw));
  std::free(raw);
}
void operator delete(void* p, std::size_t, std::align_val_t align) noexcept {
  operator delete(p, align);
}

namespace nome::bench {

std::size_t live_bytes() {
  return live.load();
}
void reset_peak() {
  base = live.load();
  peak = base.load();
}
std::size_t peak_bytes_since_reset() {
  return peak.load() - base.load();
}

}  // namespace nome::bench

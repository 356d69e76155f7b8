#include "nome/freed_memory.hpp"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>

#include "nome/buffer.hpp"

namespace nome {

void keep_freed_memory() {
  // glibc's largest mmap threshold: smaller blocks come from the heap and go back to it when freed, and
  // the heap's top is not returned to the system below 1 GB.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // Buffers' 2 MB-aligned blocks, which glibc does not reuse warm: up to a quarter of the memory, 2 GB at
  // most.
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  const std::size_t memory = pages > 0 && page > 0 ? std::size_t(pages) * std::size_t(page) : 0;
  keep_freed_buffers(std::min<std::size_t>(memory / 4, std::size_t(2) << 30));
}

}  // namespace nome

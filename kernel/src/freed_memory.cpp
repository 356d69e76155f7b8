#include "nome/freed_memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace nome {

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // no block gets its own mapping: all come from the heap
  mallopt(M_TRIM_THRESHOLD, 1 << 30);  // and freeing keeps up to 1 GB at its top for reuse
#endif
}

void release_freed_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace nome

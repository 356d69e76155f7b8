#include "nome/freed_memory.hpp"

#include <malloc.h>

namespace nome {

void keep_freed_memory() {
  // glibc's largest mmap threshold: smaller blocks come from the heap and go back to it when freed, and
  // the heap's top is not returned to the system below 1 GB.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace nome

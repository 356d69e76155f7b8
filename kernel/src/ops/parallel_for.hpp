#pragma once

#include <algorithm>

#include "nome/mesh/types.hpp"
#include "nome/worker_pool.hpp"

namespace nome {

// Runs body(begin, end) over [0, n) split into `threads` contiguous ranges, the calling thread taking the
// first. Small ranges stay on one thread: handing a range to another thread costs more than it saves below
// ~10^5 items (fewer where an item is more work).
template <class Body>
void parallel_for(Index n, int threads, const Body& body, Index min_items_per_thread = 1 << 15) {
  const Index useful = std::max<Index>(1, n / min_items_per_thread);
  const Index count = std::min<Index>(Index(std::max(threads, 1)), useful);
  if (count <= 1) {
    body(Index(0), n);
    return;
  }
  const Index chunk = (n + count - 1) / count;
  WorkerPool::shared().run(count,
                           [&](unsigned t) { body(std::min(n, t * chunk), std::min(n, (t + 1) * chunk)); });
}

}  // namespace nome

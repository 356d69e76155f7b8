#pragma once

#include <algorithm>
#include <thread>
#include <vector>

#include "nome/mesh/types.hpp"

namespace nome {

// Runs body(begin, end) over [0, n) split into `threads` contiguous ranges, the calling thread taking the
// first. Small ranges stay on one thread: starting a thread costs more than it saves below ~10^5 items
// (fewer where an item is more work).
template <class Body>
void parallel_for(Index n, int threads, const Body& body, Index min_items_per_thread = 1 << 15) {
  const Index useful = std::max<Index>(1, n / min_items_per_thread);
  const Index count = std::min<Index>(Index(std::max(threads, 1)), useful);
  if (count <= 1) {
    body(Index(0), n);
    return;
  }
  const Index chunk = (n + count - 1) / count;
  std::vector<std::thread> pool;
  pool.reserve(count - 1);
  for (Index t = 1; t < count; ++t)
    pool.emplace_back(body, std::min(n, t * chunk), std::min(n, (t + 1) * chunk));
  body(Index(0), std::min(n, chunk));
  for (std::thread& thread : pool) thread.join();
}

}  // namespace nome

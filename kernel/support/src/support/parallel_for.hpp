#pragma once

#include <algorithm>

#include "nome/index.hpp"
#include "nome/worker_pool.hpp"

namespace nome {

// Below this many items a thread, handing a range to another thread costs more than it saves (fewer where
// an item is more work: callers pass their own).
inline constexpr Index min_items_a_thread = 1 << 15;

// How many threads parallel_for gives n items: at most `threads`, and one per `min_items_per_thread`
// items.
inline Index parallel_parts(Index n, int threads, Index min_items_per_thread = min_items_a_thread) {
  return std::clamp<Index>(n / min_items_per_thread, 1, Index(std::max(threads, 1)));
}

// Runs body(begin, end) over [0, n) split into parallel_parts contiguous ranges, the calling thread taking
// the first.
template <class Body>
void parallel_for(Index n, int threads, const Body& body, Index min_items_per_thread = min_items_a_thread) {
  const Index count = parallel_parts(n, threads, min_items_per_thread);
  if (count <= 1) {
    body(Index(0), n);
    return;
  }
  const Index chunk = (n + count - 1) / count;
  WorkerPool::shared().run(count,
                           [&](unsigned t) { body(std::min(n, t * chunk), std::min(n, (t + 1) * chunk)); });
}

}  // namespace nome

#pragma once

#include "nome/worker_pool.hpp"

namespace nome {

// Runs body(part) for part in [0, parts) on that many threads, the calling thread taking part 0: for work
// split into a few interleaved shares rather than contiguous ranges (ops/parallel_for).
template <class Body>
void run_parts(int parts, const Body& body) {
  WorkerPool::shared().run(unsigned(parts), [&](unsigned part) { body(int(part)); });
}

}  // namespace nome

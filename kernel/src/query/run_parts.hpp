#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace nome {

// Runs body(part) for part in [0, parts) on that many threads, the calling thread taking part 0: for work
// split into a few interleaved shares rather than contiguous ranges (ops/parallel_for).
template <class Body>
void run_parts(int parts, const Body& body) {
  std::vector<std::thread> pool;
  for (int part = 1; part < parts; ++part) pool.emplace_back(body, part);
  body(0);
  for (std::thread& thread : pool) thread.join();
}

}  // namespace nome

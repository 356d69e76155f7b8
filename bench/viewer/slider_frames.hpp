#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace nome::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Issue 18's goal 3 on the benchmark torus (slider_torus.nome), with a current GL context: a slider that
// moves vertices at a million faces (kernel, display arrays, buffers), and whole frames at 262,144 faces
// for a slider that moves vertices and one that changes the topology.
void million_figures();
void frame_figures();

}  // namespace nome::bench

#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace nome::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the whole process (every thread), for figures on a loaded machine.
double cpu_ms();

// Live editing on the benchmark torus (slider_torus.nome), with a current GL context: a slider that
// moves vertices at a million faces (kernel, display arrays, buffers), and whole frames at 262,144 faces
// for a slider that moves vertices and one that changes the topology.
void million_figures();
void frame_figures();
// The viewer's first offset solid in a new process and warm (first_solid.cpp): the figures, and what the
// new process runs and prints for them.
void first_solid_figures();
int print_first_solid();

// The floor of a draw on this GL: the same triangles with a trivial shader (transform, constant colour)
// into the bound framebuffer, median wall and CPU (all threads) milliseconds.
struct TrivialDraw {
  double wall_ms = 0.0, cpu_ms = 0.0;
};
TrivialDraw trivial_draw(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                         const glm::mat4& transform, glm::ivec2 size);

}  // namespace nome::bench

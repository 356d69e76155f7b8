// Automatic merge on a million boundary vertices: a 500 x 500 grid of quads, every quad with its own
// four corners, merged back into one grid with a tolerance of 1e-3 of the edge length (the default,
// relative to the 707-unit diagonal, would be 0.7 edge lengths). Prints the time of merge_boundaries
// (best of three).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>

#include "nome/ops/merge.hpp"

using namespace nome;

// A lattice point moved by up to 0.3 in x and y, so points fall anywhere in the merge's grid cells.
Vec3 lattice_point(Index i, Index j) {
  const std::uint32_t h = (i * 73856093u) ^ (j * 19349663u);
  return Vec3(i + 0.3 * std::sin(double(h % 1000)), j + 0.3 * std::cos(double(h % 997)), 0.0);
}

int main() {
  constexpr Index n = 500;
  PolygonSoup soup;
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i) {
      const Index base = soup.num_vertices();
      for (Index k = 0; k < 4; ++k) soup.add_vertex(lattice_point(i + (k == 1 || k == 2), j + (k >= 2)));
      soup.add_face({base, base + 1, base + 2, base + 3});
    }
  const Mesh exploded = build_mesh(std::move(soup));

  MergeOptions options;
  options.tolerance = 1e-3;
  // Wall time and processor time: on a shared machine the wall time also counts waiting for a core.
  double best_wall = 1e30, best_cpu = 1e30;
  MergeResult result;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    result = merge_boundaries(exploded, options);
    best_cpu = std::min(best_cpu, double(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    best_wall =
        std::min(best_wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("merge: %u boundary vertices, %u faces -> %u vertices, %u edges glued: %.3f s (cpu %.3f s)\n",
              exploded.num_vertices(), exploded.num_faces(), result.mesh.num_vertices(), result.glued_edges,
              best_wall, best_cpu);
  const bool ok = result.mesh.num_vertices() == (n + 1) * (n + 1) && result.skipped.empty();
  if (!ok) std::printf("merge: unexpected result\n");
  return ok ? 0 : 1;
}

// Print check figures: the check of a 1,000,000-triangle surface on one and two threads, and of
// a surface whose offset solid has 1,000,000 triangles against the target of 1 s on two threads.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string_view>
#include <vector>

#include "nome/query/print_check.hpp"
#include "torus.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// CPU time of the process (all threads): the work done, whatever else the shared machine runs.
double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void measure(const nome::Mesh& surface, double distance, int threads, int repetitions) {
  nome::PrintCheckOptions options;
  options.offset_distance = distance;
  options.threads = threads;
  std::vector<double> times, cpu;
  // The phases' CPU times (all threads), from the check's progress reports (fold-overs, BVH, crossings,
  // near misses): what each costs whatever else the shared machine runs.
  std::vector<std::vector<double>> phases(4);
  nome::PrintCheck check;
  for (int i = 0; i < repetitions; ++i) {
    const auto start = Clock::now();
    const double cpu_start = process_cpu_ms();
    double last = cpu_start;
    int phase = 0;
    options.progress = {[&](std::string_view, double fraction) {
      if (fraction == 0.0) return;
      const double now = process_cpu_ms();
      if (phase < 4) phases[std::size_t(phase++)].push_back(now - last);
      last = now;
    }};
    check = nome::check_printability(surface, options);
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    cpu.push_back(process_cpu_ms() - cpu_start);
  }
  std::printf(
      "  offset %.3f, wall %.3f, %d thread(s): median %7.1f ms wall, %7.1f ms CPU  (fold-overs %zu, "
      "crossing pairs %zu, near misses %zu)\n",
      distance, check.min_wall, threads, median(times), median(cpu), check.fold_over_faces.size(),
      check.crossings.pairs.size(), check.near_misses.size());
  std::printf("    phases (median ms CPU): fold-overs %.1f, BVH %.1f, crossings %.1f, near misses %.1f\n",
              median(phases[0]), median(phases[1]), median(phases[2]), median(phases[3]));
}

}  // namespace

// Optional argument: repetitions per figure (default 3; the median is printed).
int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  // 708 x 708 quads: 1,002,528 triangles; its offset solid has twice as many.
  const nome::Mesh surface = nome::bench::torus(708, 708);
  std::printf("print check: torus surface of %u quads (%u triangles; its offset solid has twice as many)\n",
              surface.num_faces(), 2 * surface.num_faces());
  for (const double distance : {0.01, 0.03})
    for (const int threads : {1, 2}) measure(surface, distance, threads, repetitions);
  // A surface whose offset solid has 1,000,000 triangles, checked with that offset.
  const nome::Mesh half = nome::bench::torus(500, 500);
  std::printf(
      "print check: torus surface of %u quads whose offset solid has %u triangles   (target < 1000 ms wall "
      "on 2 threads)\n",
      half.num_faces(), 4 * half.num_faces());
  measure(half, 0.01, 2, repetitions);
}

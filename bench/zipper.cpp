// The exact (dynamic programming) zipper against the report's greedy one on random border chains:
// mean cost ratio, how often the exact strip is cheaper, triangle counts, and the solver's time on
// two 2000-point borders.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "nome/ops/zipper.hpp"
#include "support/greedy_zipper.hpp"

using namespace nome;

int main() {
  std::uniform_int_distribution<Index> size(4, 40);
  for (double penalty : {1.0, 1.3, 1.5}) {
    std::mt19937 rng{42};  // the same chains for every penalty
    ZipperOptions options;
    options.triangle_penalty = penalty;
    constexpr int trials = 1000;
    double exact_total = 0, greedy_total = 0, worst_ratio = 1;
    long exact_triangles = 0, greedy_triangles = 0;
    int cheaper = 0;
    for (int t = 0; t < trials; ++t) {
      const auto a = test::random_chain(rng, size(rng), 0.0), b = test::random_chain(rng, size(rng), 1.0);
      const ZipperStrip exact = zipper_strip(a, b, options);
      const test::GreedyStrip greedy = test::greedy_zipper(a, b, options);
      exact_total += exact.cost;
      greedy_total += greedy.cost;
      worst_ratio = std::max(worst_ratio, greedy.cost / exact.cost);
      exact_triangles += exact.triangles;
      greedy_triangles += greedy.triangles;
      cheaper += exact.cost < greedy.cost - 1e-9 ? 1 : 0;
    }
    std::printf(
        "zipper penalty %.1f: %d random chain pairs (4-40 points): greedy/exact cost %.3f (worst %.2f), "
        "exact "
        "cheaper in %d; triangles per strip exact %.2f, greedy %.2f\n",
        penalty, trials, greedy_total / exact_total, worst_ratio, cheaper, double(exact_triangles) / trials,
        double(greedy_triangles) / trials);
  }
  std::mt19937 rng{7};
  const auto a = test::random_chain(rng, 2000, 0.0), b = test::random_chain(rng, 2000, 1.0);
  const auto start = std::chrono::steady_clock::now();
  const ZipperStrip big = zipper_strip(a, b);
  std::printf("zipper: 2000 x 2000 points: %u faces in %.3f s\n", big.num_faces(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}

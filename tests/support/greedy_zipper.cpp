#include "support/greedy_zipper.hpp"

#include <limits>

namespace nome::test {

GreedyStrip greedy_zipper(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options) {
  const ZipperCost model(a, b, options);
  const Index m = model.last_a(), n = model.last_b();
  constexpr double none = std::numeric_limits<double>::infinity();
  GreedyStrip strip;
  Index i = 0, j = 0;
  while (i < m || j < n) {
    const double quad = i < m && j < n ? model.step(i + 1, j + 1, false) : none;
    const double along_a = i < m ? model.step(i + 1, j, true) : none;
    const double along_b = j < n ? model.step(i, j + 1, true) : none;
    if (quad <= along_a && quad <= along_b) {
      strip.cost += quad, ++i, ++j;
    } else if (along_a <= along_b) {
      strip.cost += along_a, ++i, ++strip.triangles;
    } else {
      strip.cost += along_b, ++j, ++strip.triangles;
    }
  }
  return strip;
}

std::vector<Vec3> random_chain(std::mt19937& rng, Index points, double y) {
  std::uniform_real_distribution<double> step(0.2, 1.5), wobble(-0.3, 0.3);
  std::vector<Vec3> chain;
  double x = 0.0;
  for (Index k = 0; k < points; ++k) {
    chain.emplace_back(x, y + wobble(rng), wobble(rng));
    x += step(rng);
  }
  return chain;
}

}  // namespace nome::test

#pragma once

#include <random>
#include <span>
#include <vector>

#include "nome/ops/zipper.hpp"

namespace nome::test {

struct GreedyStrip {
  double cost = 0.0;
  Index triangles = 0;
};

// The report's zipper (Wang 2016, 7.3.3), the reference the exact solver is compared with: from the
// first rung, repeatedly add the cheapest next face. Costs come from the same ZipperCost model.
GreedyStrip greedy_zipper(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options);

// A wobbly border chain along +x near the line y = `y`, steps of 0.2 to 1.5.
std::vector<Vec3> random_chain(std::mt19937& rng, Index points, double y);

}  // namespace nome::test

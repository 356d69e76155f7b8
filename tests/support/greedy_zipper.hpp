#pragma once

#include <span>

#include "nome/ops/zipper.hpp"

namespace nome::test {

struct GreedyStrip {
  double cost = 0.0;
  Index triangles = 0;
};

// The report's zipper (Wang 2016, 7.3.3), the reference the exact solver is compared with: from the
// first rung, repeatedly add the cheapest next face. Costs come from the same ZipperCost model.
GreedyStrip greedy_zipper(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options);

}  // namespace nome::test

#pragma once

#include <limits>
#include <span>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace nome::render {

// Axis-aligned box; empty until a point is added.
struct BoundingBox {
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};

  void add(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  bool is_empty() const { return !(min.x <= max.x); }
  glm::dvec3 center() const { return 0.5 * (min + max); }
  glm::dvec3 corner(int i) const {
    return {i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z};
  }

  static BoundingBox of(std::span<const glm::dvec3> points) {
    BoundingBox box;
    for (const auto& p : points) box.add(p);
    return box;
  }
};

}  // namespace nome::render

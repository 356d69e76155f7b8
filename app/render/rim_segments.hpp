#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/query/rim_pick.hpp"

namespace nome::render {

// Polylines as GL line segments: points, and two indices into them per segment.
struct LineSegments {
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> segments;

  bool empty() const { return segments.empty(); }
};

// Adds each rim line's points joined in order, a closed line of three or more points back to its first.
void add_rim_segments(const RimLines& lines, LineSegments& out);

}  // namespace nome::render

#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "nome/query/rim_pick.hpp"

namespace nome::render {

// Polylines as GL line segments: points, and two indices into them per segment; per point a colour
// (alpha 0: the rim colour), or none while no line has its own.
struct LineSegments {
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> segments;
  std::vector<glm::vec4> colors;

  bool empty() const { return segments.empty(); }
};

// Adds each rim line's points joined in order, a closed line of three or more points back to its first,
// in its surface's colour where it has one.
void add_rim_segments(const RimLines& lines, LineSegments& out);

}  // namespace nome::render

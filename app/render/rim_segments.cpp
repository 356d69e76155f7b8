#include "render/rim_segments.hpp"

namespace nome::render {

void add_rim_segments(const RimLines& lines, LineSegments& out) {
  for (Index l = 0; l < lines.num_lines(); ++l) {
    const auto first = std::uint32_t(out.points.size()), n = lines.offsets[l + 1] - lines.offsets[l];
    for (Index v = lines.offsets[l]; v < lines.offsets[l + 1]; ++v)
      out.points.push_back(glm::vec3(lines.positions[v]));
    for (std::uint32_t i = 0; i + 1 < n; ++i)
      out.segments.insert(out.segments.end(), {first + i, first + i + 1});
    if (lines.is_closed[l] && n > 2) out.segments.insert(out.segments.end(), {first + n - 1, first});
  }
}

}  // namespace nome::render

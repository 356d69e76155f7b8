#include "render/rim_segments.hpp"

#include <algorithm>

namespace nome::render {

void add_rim_segments(const RimLines& lines, LineSegments& out) {
  const bool has_colors = std::any_of(lines.colors.begin(), lines.colors.end(),
                                      [](const std::optional<Color>& c) { return c.has_value(); });
  const bool keeps_colors = has_colors || !out.colors.empty();
  if (keeps_colors) out.colors.resize(out.points.size(), glm::vec4(0.0f));
  for (Index l = 0; l < lines.num_lines(); ++l) {
    const auto first = std::uint32_t(out.points.size()), n = lines.offsets[l + 1] - lines.offsets[l];
    for (Index v = lines.offsets[l]; v < lines.offsets[l + 1]; ++v)
      out.points.push_back(glm::vec3(lines.positions[v]));
    if (keeps_colors) {
      const std::optional<Color>& c = l < lines.colors.size() ? lines.colors[l] : std::nullopt;
      out.colors.resize(out.points.size(), c ? glm::vec4(*c, 1.0f) : glm::vec4(0.0f));
    }
    for (std::uint32_t i = 0; i + 1 < n; ++i)
      out.segments.insert(out.segments.end(), {first + i, first + i + 1});
    if (lines.is_closed[l] && n > 2) out.segments.insert(out.segments.end(), {first + n - 1, first});
  }
}

}  // namespace nome::render

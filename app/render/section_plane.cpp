#include "render/section_plane.hpp"

#include <algorithm>

namespace nome::render {

std::optional<SectionAxis> parse_section_axis(std::string_view name) {
  if (name == "x") return SectionAxis::x;
  if (name == "y") return SectionAxis::y;
  if (name == "z") return SectionAxis::z;
  return std::nullopt;
}

glm::vec4 section_plane(SectionAxis axis, double at) {
  glm::vec4 plane(0.0f);
  plane[int(axis)] = 1.0f;
  plane.w = float(-at);
  return plane;
}

double section_centre(const Mesh& mesh, SectionAxis axis) {
  if (mesh.num_vertices() == 0) return 0.0;
  double low = mesh.position(0)[int(axis)], high = low;
  for (const Vec3& p : mesh.positions()) {
    low = std::min(low, p[int(axis)]);
    high = std::max(high, p[int(axis)]);
  }
  return 0.5 * (low + high);
}

}  // namespace nome::render

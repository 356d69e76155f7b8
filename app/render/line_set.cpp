#include "render/line_set.hpp"

#include <vector>

#include "nome/error.hpp"

namespace nome::render {

LineSet::LineSet() : points_(vec3_texels, 0) {
  glGenBuffers(1, &ends_);
  glGenBuffers(1, &colors_);
  vao_ = make_segment_vao(ends_);
  glBindVertexArray(0);
}

LineSet::~LineSet() {
  glDeleteVertexArrays(1, &vao_);
  const GLuint buffers[] = {ends_, colors_};
  glDeleteBuffers(2, buffers);
}

void LineSet::set(std::span<const glm::vec3> points, std::span<const std::uint32_t> segments,
                  std::span<const glm::vec4> colors) {
  if (segments.size() % 2 != 0) throw InvalidInputError("LineSet::set: an odd number of segment ends");
  if (!colors.empty() && colors.size() != points.size())
    throw InvalidInputError("LineSet::set: " + std::to_string(colors.size()) + " colours for " +
                            std::to_string(points.size()) + " points");
  for (std::uint32_t i : segments)
    if (i >= points.size())
      throw InvalidInputError("LineSet::set: segment end " + std::to_string(i) + " past the points");
  points_.resize(points.size());
  points_.write(points.data(), points.size());
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, ends_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(segments.size_bytes()), segments.data(), GL_DYNAMIC_DRAW);
  // Without colours the attribute is off and reads the renderer's constant (alpha 0: the draw's colour).
  if (colors.empty()) {
    glDisableVertexAttribArray(1);
  } else {
    std::vector<glm::vec4> segment_colors(segments.size() / 2);
    for (std::size_t s = 0; s < segment_colors.size(); ++s) segment_colors[s] = colors[segments[2 * s]];
    glBindBuffer(GL_ARRAY_BUFFER, colors_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(segment_colors.size() * sizeof(glm::vec4)),
                 segment_colors.data(), GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  glBindVertexArray(0);
  segment_count_ = std::uint32_t(segments.size() / 2);
}

void LineSet::set_polyline(std::span<const glm::vec3> points, bool is_closed) {
  std::vector<std::uint32_t> segments;
  const std::uint32_t n = std::uint32_t(points.size());
  for (std::uint32_t i = 0; n >= 2 && i + (is_closed ? 0 : 1) < n; ++i) {
    segments.push_back(i);
    segments.push_back((i + 1) % n);
  }
  set(points, segments);
}

}  // namespace nome::render

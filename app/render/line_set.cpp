#include "render/line_set.hpp"

#include <vector>

#include "nome/error.hpp"

namespace nome::render {

LineSet::LineSet() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &points_);
  glGenBuffers(1, &colors_);
  glGenBuffers(1, &indices_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, points_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
  glBindVertexArray(0);
}

LineSet::~LineSet() {
  glDeleteVertexArrays(1, &vao_);
  const GLuint buffers[] = {points_, colors_, indices_};
  glDeleteBuffers(3, buffers);
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
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, points_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(points.size_bytes()), points.data(), GL_DYNAMIC_DRAW);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(segments.size_bytes()), segments.data(), GL_DYNAMIC_DRAW);
  // Without colours the attribute is off and reads the renderer's constant (alpha 0: the draw's colour).
  if (colors.empty()) {
    glDisableVertexAttribArray(1);
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, colors_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(colors.size_bytes()), colors.data(), GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  glBindVertexArray(0);
  index_count_ = GLsizei(segments.size());
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

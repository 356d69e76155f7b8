#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "render/gl.hpp"

namespace nome::render {

// Segments on the GPU for overlays: selected borders, polylines, temporary edges. Drawn by
// Renderer::draw_lines at any pixel width. Needs a current context for its whole life.
class LineSet {
 public:
  LineSet();
  ~LineSet();
  LineSet(const LineSet&) = delete;
  LineSet& operator=(const LineSet&) = delete;

  // Replaces the content: `segments` holds two indices into `points` per segment.
  void set(std::span<const glm::vec3> points, std::span<const std::uint32_t> segments);
  // Convenience: consecutive points joined, closing the loop when asked.
  void set_polyline(std::span<const glm::vec3> points, bool is_closed);

  GLuint vao() const { return vao_; }
  GLsizei index_count() const { return index_count_; }

 private:
  GLuint vao_ = 0, points_ = 0, indices_ = 0;
  GLsizei index_count_ = 0;
};

}  // namespace nome::render

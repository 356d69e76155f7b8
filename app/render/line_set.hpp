#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gl.hpp"
#include "render/segment_source.hpp"
#include "render/table_texture.hpp"

namespace nome::render {

// Segments on the GPU for overlays: selected borders, polylines, temporary edges. Drawn by
// Renderer::draw_lines at any pixel width. Needs a current context for its whole life.
class LineSet {
 public:
  LineSet();
  ~LineSet();
  LineSet(const LineSet&) = delete;
  LineSet& operator=(const LineSet&) = delete;

  // Replaces the content: `segments` holds two indices into `points` per segment. `colors`, empty or one
  // per point, gives a segment the colour of its first point where its alpha is nonzero; the others take
  // the colour they are drawn in.
  void set(std::span<const glm::vec3> points, std::span<const std::uint32_t> segments,
           std::span<const glm::vec4> colors = {});
  // Convenience: consecutive points joined, closing the loop when asked.
  void set_polyline(std::span<const glm::vec3> points, bool is_closed);

  SegmentSource segments() const { return {vao_, ends_, points_.id(), {0, segment_count_}}; }

 private:
  TableTexture points_;
  GLuint vao_ = 0, ends_ = 0, colors_ = 0;  // colours: one per segment, its first point's
  std::uint32_t segment_count_ = 0;
};

}  // namespace nome::render

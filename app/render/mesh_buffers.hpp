#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "nome/mesh/types.hpp"
#include "render/gl.hpp"
#include "render/mesh_display_data.hpp"

namespace nome::render {

// A mesh on the GPU: the corner vertices and triangles, the edge segments, and two per-face tables
// (colour, selection flags) that the viewer updates without re-uploading the geometry. Needs a current
// context for its whole life.
class MeshBuffers {
 public:
  explicit MeshBuffers(const MeshDisplayData& data);
  ~MeshBuffers();
  MeshBuffers(const MeshBuffers&) = delete;
  MeshBuffers& operator=(const MeshBuffers&) = delete;

  // Replaces the per-face colours (RGBA; alpha 0 = the display's front colour); one per face.
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors);
  // Marks these faces selected (tinted); all others unselected.
  void set_selected_faces(std::span<const Index> faces);

  GLuint surface_vao() const { return surface_vao_; }
  GLuint edge_vao() const { return edge_vao_; }
  GLsizei triangle_index_count() const { return triangle_index_count_; }
  SegmentRange all_edges() const { return all_edges_; }
  SegmentRange mobius_edges() const { return mobius_edges_; }
  SegmentRange border_edges() const { return border_edges_; }
  GLuint face_color_texture() const { return face_color_texture_; }
  GLuint face_flag_texture() const { return face_flag_texture_; }
  const BoundingBox& bounds() const { return bounds_; }

 private:
  std::uint32_t num_faces_;
  GLuint surface_vao_ = 0, edge_vao_ = 0;
  std::array<GLuint, 8> buffers_{};  // positions, normals x2, faces, triangles, vertices, segments, spare
  GLuint face_color_buffer_ = 0, face_flag_buffer_ = 0;
  GLuint face_color_texture_ = 0, face_flag_texture_ = 0;
  GLsizei triangle_index_count_ = 0;
  SegmentRange all_edges_, mobius_edges_, border_edges_;
  BoundingBox bounds_;
};

}  // namespace nome::render

#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "nome/mesh/types.hpp"
#include "render/gl.hpp"
#include "render/mesh_display_data.hpp"
#include "render/segment_source.hpp"
#include "render/table_texture.hpp"

namespace nome::render {

// A mesh on the GPU: its topology (GL vertices carrying a face id, triangles, edge segments), positions and
// normals as vertex arrays, and three per-face tables (normal, colour, selection flags; table textures).
// Positions, normals and tables are updated in place (into the buffers and textures already there): a
// slider that moves vertices uploads three floats and a packed normal per vertex and a packed normal per
// face, nothing per corner. The edges read the mesh's vertices from a table of their own, copied from the
// positions on the GPU's side when edges are drawn. Needs a current context for its whole life.
class MeshBuffers {
 public:
  explicit MeshBuffers(const MeshDisplayData& data);
  ~MeshBuffers();
  MeshBuffers(const MeshBuffers&) = delete;
  MeshBuffers& operator=(const MeshBuffers&) = delete;

  // The topology uploaded: data of the same one can take update_positions().
  const DisplayTopology& topology() const { return *topology_; }
  // New positions and normals for the same topology; throws InvalidInputError when the counts differ.
  void update_positions(const DisplayPositions& positions);
  // Replaces the per-face colours (RGBA; alpha 0 = the display's front colour): one per face, or none.
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors);
  // Marks these faces selected (tinted); all others unselected.
  void set_selected_faces(std::span<const Index> faces);

  GLuint surface_vao() const { return surface_vao_; }
  GLsizei triangle_index_count() const { return GLsizei(topology_->triangles.size()); }
  SegmentRange all_edges() const { return topology_->all_edges; }
  SegmentRange mobius_edges() const { return topology_->mobius_edges; }
  SegmentRange border_edges() const { return topology_->border_edges; }
  // Whether some face has a colour of its own / is selected: else the fragments skip those tables.
  bool has_face_colors() const { return has_face_colors_; }
  bool has_selection() const { return has_selection_; }
  GLuint face_color_texture() const { return face_colors_.id(); }
  GLuint face_flag_texture() const { return face_flags_.id(); }
  // A PackedNormal per face (an R32I table, unpacked by the shader).
  GLuint face_normal_texture() const { return face_normals_.id(); }
  // These segments of the topology's, over the current positions.
  SegmentSource edges(SegmentRange range) const { return {edge_vao_, buffers_[4], edge_points(), range}; }

 private:
  GLuint edge_points() const;

  std::shared_ptr<const DisplayTopology> topology_;

  GLuint surface_vao_ = 0, edge_vao_ = 0;
  // positions, vertex normals, vertex faces, triangles, segments
  std::array<GLuint, 5> buffers_{};
  TableTexture face_normals_, face_colors_, face_flags_;
  // The edges' points, brought up to date by the first draw of edges after the vertices moved: a slider
  // without the wireframe pays nothing for them.
  TableTexture edge_points_;
  mutable bool are_edge_points_stale_ = true;
  bool has_face_colors_ = false, has_selection_ = false;
};

}  // namespace nome::render

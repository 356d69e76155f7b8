#include "render/mesh_buffers.hpp"

#include <algorithm>
#include <span>
#include <type_traits>
#include <vector>

#include "nome/error.hpp"

namespace nome::render {
namespace {

template <typename Array>
void upload(GLenum target, GLuint buffer, const Array& data, GLenum usage = GL_STATIC_DRAW) {
  glBindBuffer(target, buffer);
  glBufferData(target, GLsizeiptr(data.size() * sizeof(data[0])), data.empty() ? nullptr : data.data(),
               usage);
}

void uint_attribute(GLuint location, GLuint buffer) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(location);
  glVertexAttribIPointer(location, 1, GL_UNSIGNED_INT, 0, nullptr);
}

// An array of `count` elements of type T per vertex, written by update_positions(): three floats, or a
// PackedNormal (signed normalized 2_10_10_10_REV, read by the shader as a vec3).
template <class T>
void vertex_attribute(GLuint location, GLuint buffer, std::size_t count) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(std::max<std::size_t>(count, 1) * sizeof(T)), nullptr,
               GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(location);
  if constexpr (std::is_same_v<T, PackedNormal>)
    glVertexAttribPointer(location, 4, GL_INT_2_10_10_10_REV, GL_TRUE, 0, nullptr);
  else
    glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
}

template <class T>
void write_array(GLenum target, GLuint buffer, std::size_t first, std::span<const T> data) {
  if (data.empty()) return;
  glBindBuffer(target, buffer);
  glBufferSubData(target, GLintptr(first * sizeof(T)), GLsizeiptr(data.size() * sizeof(T)), data.data());
}

}  // namespace

MeshBuffers::MeshBuffers(const MeshDisplayData& data)
    : topology_(data.topology),
      face_normals_(int_texels, topology_->num_faces),
      face_colors_(rgba8_texels, topology_->num_faces),
      face_flags_(byte_texels, topology_->num_faces),
      edge_points_(vec3_texels, topology_->num_vertices) {
  const DisplayTopology& t = *topology_;
  glGenBuffers(GLsizei(buffers_.size()), buffers_.data());
  glGenVertexArrays(1, &surface_vao_);
  glBindVertexArray(surface_vao_);
  vertex_attribute<glm::vec3>(0, buffers_[0], t.num_gl_vertices());
  vertex_attribute<PackedNormal>(1, buffers_[1], t.num_gl_vertices());
  upload(GL_ARRAY_BUFFER, buffers_[2], t.vertex_faces);
  uint_attribute(2, buffers_[2]);
  upload(GL_ELEMENT_ARRAY_BUFFER, buffers_[3], t.triangles);

  upload(GL_ARRAY_BUFFER, buffers_[4], t.segments);
  edge_vao_ = make_segment_vao(buffers_[4]);
  glBindVertexArray(0);
  update_positions(*data.positions);
  set_face_colors(data.face_colors);
  set_selected_faces({});
}

MeshBuffers::~MeshBuffers() {
  glDeleteVertexArrays(1, &surface_vao_);
  glDeleteVertexArrays(1, &edge_vao_);
  glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
}

void MeshBuffers::update_positions(const DisplayPositions& positions) {
  const DisplayTopology& t = *topology_;
  const std::size_t extra = t.extra_vertices.size();
  if (positions.vertices.size() != t.num_vertices || positions.vertex_normals.size() != t.num_vertices ||
      positions.face_normals.size() != t.num_faces || positions.extra_vertices.size() != extra ||
      positions.extra_normals.size() != extra)
    throw InvalidInputError("MeshBuffers::update_positions: " + std::to_string(positions.vertices.size()) +
                            " vertices, " + std::to_string(positions.extra_vertices.size()) +
                            " extra vertices and " + std::to_string(positions.face_normals.size()) +
                            " faces for " + std::to_string(t.num_vertices) + ", " + std::to_string(extra) +
                            " and " + std::to_string(t.num_faces));
  write_array<glm::vec3>(GL_ARRAY_BUFFER, buffers_[0], 0, positions.vertices);
  write_array<glm::vec3>(GL_ARRAY_BUFFER, buffers_[0], t.num_vertices, positions.extra_vertices);
  write_array<PackedNormal>(GL_ARRAY_BUFFER, buffers_[1], 0, positions.vertex_normals);
  write_array<PackedNormal>(GL_ARRAY_BUFFER, buffers_[1], t.num_vertices, positions.extra_normals);
  face_normals_.write(positions.face_normals.data(), positions.face_normals.size());
  are_edge_points_stale_ = true;
}

void MeshBuffers::set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) {
  if (!colors.empty() && colors.size() != topology_->num_faces)
    throw InvalidInputError("MeshBuffers::set_face_colors: " + std::to_string(colors.size()) +
                            " colours for " + std::to_string(topology_->num_faces) + " faces");
  const bool had_face_colors = has_face_colors_;
  has_face_colors_ = std::any_of(colors.begin(), colors.end(), [](const auto& c) { return c[3] > 0; });
  // Without colours the table is never read: a slider on an uncoloured mesh uploads none.
  if (!has_face_colors_ && !had_face_colors) return;
  face_colors_.write(colors.data(), colors.size());
}

void MeshBuffers::set_selected_faces(std::span<const Index> faces) {
  const std::uint32_t num_faces = topology_->num_faces;
  std::vector<std::uint8_t> flags(num_faces, 0);
  for (Index f : faces) {
    if (f >= num_faces)
      throw InvalidInputError("MeshBuffers::set_selected_faces: face " + std::to_string(f) + " of " +
                              std::to_string(num_faces));
    flags[f] = 1;
  }
  has_selection_ = !faces.empty();
  face_flags_.write(flags.data(), flags.size());
}

GLuint MeshBuffers::edge_points() const {
  if (are_edge_points_stale_) {
    // The mesh's own vertices, the first of the positions buffer, copied on the GPU's side.
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]);
    edge_points_.write(nullptr, topology_->num_vertices);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    are_edge_points_stale_ = false;
  }
  return edge_points_.id();
}

}  // namespace nome::render

#include "render/mesh_buffers.hpp"

#include <vector>

#include "nome/error.hpp"

namespace nome::render {
namespace {

template <typename T>
void upload(GLenum target, GLuint buffer, const std::vector<T>& data) {
  glBindBuffer(target, buffer);
  glBufferData(target, GLsizeiptr(data.size() * sizeof(T)), data.empty() ? nullptr : data.data(),
               GL_STATIC_DRAW);
}

void float_attribute(GLuint location, GLuint buffer, GLint size) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, 0, nullptr);
}

// A buffer texture: per-face tables of any length indexed by face id in the fragment shader.
void make_table(GLuint& buffer, GLuint& texture, GLenum format, std::size_t bytes) {
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  // An empty buffer texture is undefined to sample: keep one entry.
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(std::max<std::size_t>(bytes, 4)), nullptr, GL_DYNAMIC_DRAW);
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_BUFFER, texture);
  glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
}

}  // namespace

MeshBuffers::MeshBuffers(const MeshDisplayData& data)
    : num_faces_(data.num_faces),
      all_edges_(data.all_edges),
      mobius_edges_(data.mobius_edges),
      border_edges_(data.border_edges),
      bounds_(data.bounds) {
  glGenBuffers(GLsizei(buffers_.size()), buffers_.data());
  glGenVertexArrays(1, &surface_vao_);
  glBindVertexArray(surface_vao_);
  upload(GL_ARRAY_BUFFER, buffers_[0], data.corner_positions);
  float_attribute(0, buffers_[0], 3);
  upload(GL_ARRAY_BUFFER, buffers_[1], data.smooth_normals);
  float_attribute(1, buffers_[1], 3);
  upload(GL_ARRAY_BUFFER, buffers_[2], data.flat_normals);
  float_attribute(2, buffers_[2], 3);
  upload(GL_ARRAY_BUFFER, buffers_[3], data.corner_faces);
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_UNSIGNED_INT, 0, nullptr);
  upload(GL_ELEMENT_ARRAY_BUFFER, buffers_[4], data.triangles);
  triangle_index_count_ = GLsizei(data.triangles.size());

  glGenVertexArrays(1, &edge_vao_);
  glBindVertexArray(edge_vao_);
  upload(GL_ARRAY_BUFFER, buffers_[5], data.vertex_positions);
  float_attribute(0, buffers_[5], 3);
  upload(GL_ELEMENT_ARRAY_BUFFER, buffers_[6], data.segments);
  glBindVertexArray(0);

  make_table(face_color_buffer_, face_color_texture_, GL_RGBA8, std::size_t(num_faces_) * 4);
  make_table(face_flag_buffer_, face_flag_texture_, GL_R8UI, num_faces_);
  set_face_colors(data.face_colors);
  set_selected_faces({});
}

MeshBuffers::~MeshBuffers() {
  glDeleteVertexArrays(1, &surface_vao_);
  glDeleteVertexArrays(1, &edge_vao_);
  glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  const GLuint tables[] = {face_color_buffer_, face_flag_buffer_};
  glDeleteBuffers(2, tables);
  const GLuint textures[] = {face_color_texture_, face_flag_texture_};
  glDeleteTextures(2, textures);
}

void MeshBuffers::set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) {
  if (colors.size() != num_faces_)
    throw InvalidInputError("MeshBuffers::set_face_colors: " + std::to_string(colors.size()) +
                            " colours for " + std::to_string(num_faces_) + " faces");
  glBindBuffer(GL_TEXTURE_BUFFER, face_color_buffer_);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(colors.size() * 4), colors.data());
}

void MeshBuffers::set_selected_faces(std::span<const Index> faces) {
  std::vector<std::uint8_t> flags(num_faces_, 0);
  for (Index f : faces) {
    if (f >= num_faces_)
      throw InvalidInputError("MeshBuffers::set_selected_faces: face " + std::to_string(f) + " of " +
                              std::to_string(num_faces_));
    flags[f] = 1;
  }
  glBindBuffer(GL_TEXTURE_BUFFER, face_flag_buffer_);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(flags.size()), flags.data());
}

}  // namespace nome::render

#include "render/mesh_buffers.hpp"

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

// Three floats per element, read as R32F texels (GL 3.3 has no three-component buffer textures): sized
// for at least one element, since an empty buffer texture is undefined to sample.
void make_vectors(GLuint buffer, GLuint texture, std::size_t count) {
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(std::max<std::size_t>(count, 1) * sizeof(glm::vec3)), nullptr,
               GL_DYNAMIC_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, texture);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, buffer);
}

void write_vectors(GLuint buffer, const Buffer<glm::vec3>& data) {
  if (data.empty()) return;
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(data.size() * sizeof(glm::vec3)), data.data());
}

}  // namespace

MeshBuffers::MeshBuffers(const MeshDisplayData& data) : topology_(data.topology) {
  const DisplayTopology& t = *topology_;
  glGenBuffers(GLsizei(buffers_.size()), buffers_.data());
  glGenTextures(GLsizei(textures_.size()), textures_.data());
  make_vectors(buffers_[0], textures_[0], t.num_vertices);
  make_vectors(buffers_[1], textures_[1], t.num_vertices);
  make_vectors(buffers_[2], textures_[2], t.num_faces);
  glGenVertexArrays(1, &surface_vao_);
  glBindVertexArray(surface_vao_);
  upload(GL_ARRAY_BUFFER, buffers_[3], t.corner_vertices);
  uint_attribute(0, buffers_[3]);
  upload(GL_ARRAY_BUFFER, buffers_[4], t.corner_faces);
  uint_attribute(1, buffers_[4]);
  upload(GL_ELEMENT_ARRAY_BUFFER, buffers_[5], t.triangles);

  // The wireframe reads the positions buffer as a plain vertex array.
  glGenVertexArrays(1, &edge_vao_);
  glBindVertexArray(edge_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  upload(GL_ELEMENT_ARRAY_BUFFER, buffers_[6], t.segments);
  glBindVertexArray(0);

  make_table(face_color_buffer_, face_color_texture_, GL_RGBA8, std::size_t(t.num_faces) * 4);
  make_table(face_flag_buffer_, face_flag_texture_, GL_R8UI, t.num_faces);
  update_positions(*data.positions);
  set_face_colors(data.face_colors);
  set_selected_faces({});
}

MeshBuffers::~MeshBuffers() {
  glDeleteVertexArrays(1, &surface_vao_);
  glDeleteVertexArrays(1, &edge_vao_);
  glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  glDeleteTextures(GLsizei(textures_.size()), textures_.data());
  const GLuint tables[] = {face_color_buffer_, face_flag_buffer_};
  glDeleteBuffers(2, tables);
  const GLuint textures[] = {face_color_texture_, face_flag_texture_};
  glDeleteTextures(2, textures);
}

void MeshBuffers::update_positions(const DisplayPositions& positions) {
  const DisplayTopology& t = *topology_;
  if (positions.vertices.size() != t.num_vertices || positions.vertex_normals.size() != t.num_vertices ||
      positions.face_normals.size() != t.num_faces)
    throw InvalidInputError("MeshBuffers::update_positions: " + std::to_string(positions.vertices.size()) +
                            " vertices and " + std::to_string(positions.face_normals.size()) + " faces for " +
                            std::to_string(t.num_vertices) + " and " + std::to_string(t.num_faces));
  write_vectors(buffers_[0], positions.vertices);
  write_vectors(buffers_[1], positions.vertex_normals);
  write_vectors(buffers_[2], positions.face_normals);
  bounds_ = positions.bounds;
}

void MeshBuffers::set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) {
  if (colors.size() != topology_->num_faces)
    throw InvalidInputError("MeshBuffers::set_face_colors: " + std::to_string(colors.size()) +
                            " colours for " + std::to_string(topology_->num_faces) + " faces");
  glBindBuffer(GL_TEXTURE_BUFFER, face_color_buffer_);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(colors.size() * 4), colors.data());
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
  glBindBuffer(GL_TEXTURE_BUFFER, face_flag_buffer_);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(flags.size()), flags.data());
}

}  // namespace nome::render

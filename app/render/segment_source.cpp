#include "render/segment_source.hpp"

namespace nome::render {

GLuint make_segment_vao(GLuint ends) {
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, ends);
  glEnableVertexAttribArray(0);
  glVertexAttribIPointer(0, 2, GL_UNSIGNED_INT, 0, nullptr);
  glVertexAttribDivisor(0, 1);
  glVertexAttribDivisor(1, 1);
  return vao;
}

}  // namespace nome::render

#include <chrono>
#include <vector>

#include "render/gl.hpp"
#include "slider_frames.hpp"

namespace nome::bench {
namespace {

const char* const vertex_source = R"(#version 330
layout(location = 0) in vec3 position;
uniform mat4 transform;
void main() { gl_Position = transform * vec4(position, 1.0); })";
const char* const fragment_source = R"(#version 330
out vec4 fragment;
void main() { fragment = vec4(0.5, 0.5, 0.5, 1.0); })";

GLuint program() {
  const GLuint p = glCreateProgram();
  for (const auto& [type, source] :
       {std::pair{GL_VERTEX_SHADER, vertex_source}, {GL_FRAGMENT_SHADER, fragment_source}}) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  return p;
}

}  // namespace

TrivialDraw trivial_draw(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangles,
                         const glm::mat4& transform, glm::ivec2 size) {
  const GLuint p = program();
  GLuint vao = 0, buffers[2] = {};
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(positions.size_bytes()), positions.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(triangles.size_bytes()), triangles.data(), GL_STATIC_DRAW);
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "transform"), 1, GL_FALSE, &transform[0][0]);
  glEnable(GL_DEPTH_TEST);
  std::vector<double> wall, cpu;
  for (int i = 0; i < 5; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_ms();
    glViewport(0, 0, size.x, size.y);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(triangles.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
    wall.push_back(ms_since(start));
    cpu.push_back(cpu_ms() - cpu_start);
  }
  glBindVertexArray(0);
  glDeleteBuffers(2, buffers);
  glDeleteVertexArrays(1, &vao);
  glDeleteProgram(p);
  return {median(wall), median(cpu)};
}

}  // namespace nome::bench

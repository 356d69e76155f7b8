#include "render/cube_set.hpp"

#include <cstddef>
#include <vector>

namespace nome::render {
namespace {

// 36 vertices: position then normal, six faces counter-clockwise from outside.
std::vector<float> unit_cube() {
  std::vector<float> data;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const float square[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      const int order[6] = {0, 1, 2, 0, 2, 3};
      for (int k : order) {
        float p[3], n[3] = {0, 0, 0};
        p[axis] = float(sign);
        // Swapping the in-plane axes on the negative side keeps every face counter-clockwise outside.
        p[u] = square[k][sign > 0 ? 0 : 1];
        p[v] = square[k][sign > 0 ? 1 : 0];
        n[axis] = float(sign);
        data.insert(data.end(), p, p + 3);
        data.insert(data.end(), n, n + 3);
      }
    }
  }
  return data;
}

}  // namespace

CubeSet::CubeSet() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &shape_);
  glGenBuffers(1, &instances_);
  glBindVertexArray(vao_);
  const std::vector<float> cube = unit_cube();
  glBindBuffer(GL_ARRAY_BUFFER, shape_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cube.size() * sizeof(float)), cube.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<void*>(3 * sizeof(float)));
  glBindBuffer(GL_ARRAY_BUFFER, instances_);
  const auto stride = GLsizei(sizeof(CubeMarker));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(CubeMarker, center)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(CubeMarker, half_size)));
  glEnableVertexAttribArray(4);
  glVertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(CubeMarker, color)));
  for (GLuint a = 2; a <= 4; ++a) glVertexAttribDivisor(a, 1);
  glBindVertexArray(0);
}

CubeSet::~CubeSet() {
  glDeleteVertexArrays(1, &vao_);
  const GLuint buffers[] = {shape_, instances_};
  glDeleteBuffers(2, buffers);
}

void CubeSet::set(std::span<const CubeMarker> cubes) {
  glBindBuffer(GL_ARRAY_BUFFER, instances_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cubes.size_bytes()), cubes.data(), GL_DYNAMIC_DRAW);
  count_ = GLsizei(cubes.size());
}

}  // namespace nome::render

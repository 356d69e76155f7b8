#include "render/cube_set.hpp"

#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "render/bounding_box.hpp"

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

std::vector<CubeMarker> vertex_markers(const Mesh& mesh, std::span<const Index> vertices,
                                       const glm::vec3& color) {
  constexpr double fraction_of_edge = 0.12;
  std::vector<CubeMarker> markers;
  markers.reserve(vertices.size());
  for (Index v : vertices) {
    if (v >= mesh.num_vertices())
      throw InvalidInputError("vertex_markers: vertex " + std::to_string(v) + " of " +
                              std::to_string(mesh.num_vertices()));
    double length = 0.0;
    const auto edges = mesh.vertex_edges(v);
    for (Index e : edges)
      length += glm::length(mesh.position(mesh.edge(e).other_vertex(v)) - mesh.position(v));
    // An isolated vertex has no edges: fall back to a fraction of the mesh's size.
    if (edges.empty()) {
      BoundingBox box = BoundingBox::of(mesh.positions());
      length = box.is_empty() ? 1.0 : std::max(glm::length(box.max - box.min) * 0.05, 1e-9);
    } else {
      length /= double(edges.size());
    }
    markers.push_back({glm::vec3(mesh.position(v)), float(fraction_of_edge * length), color});
  }
  return markers;
}

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

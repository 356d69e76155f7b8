#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/mesh/mesh.hpp"
#include "render/gl.hpp"

namespace nome::render {

// A small lit cube at a point, as the report marks selected vertices.
struct CubeMarker {
  glm::vec3 center;
  float half_size;
  glm::vec3 color;
};

// Markers for mesh vertices, each cube sized by the vertex's local edge length (a fraction of the mean
// length of its edges), so it stays visible and never swallows its neighbours.
std::vector<CubeMarker> vertex_markers(const Mesh& mesh, std::span<const Index> vertices,
                                       const glm::vec3& color);

// Cube markers on the GPU, drawn instanced by Renderer::draw_cubes. Needs a current context.
class CubeSet {
 public:
  CubeSet();
  ~CubeSet();
  CubeSet(const CubeSet&) = delete;
  CubeSet& operator=(const CubeSet&) = delete;

  void set(std::span<const CubeMarker> cubes);

  GLuint vao() const { return vao_; }
  GLsizei count() const { return count_; }

 private:
  GLuint vao_ = 0, shape_ = 0, instances_ = 0;
  GLsizei count_ = 0;
};

}  // namespace nome::render

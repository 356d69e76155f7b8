#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/mesh/mesh.hpp"
#include "render/bounding_box.hpp"

namespace nome::render {

// A range of segments in MeshDisplayData::segments.
struct SegmentRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

// What the GPU needs to draw a kernel Mesh, built on the CPU (testable without GL):
// - one vertex per face corner with the smooth normal (the vertex normal turned into the face's own
//   orientation by the corner's sign: Möbius-aware) and the flat normal, triangulated by the kernel;
// - the mesh's real edges as segments over its vertices: all edges, the Möbius ones, the border ones;
// - per-face RGBA colours (alpha 0 where the face has none).
struct MeshDisplayData {
  std::vector<glm::vec3> corner_positions;
  std::vector<glm::vec3> smooth_normals;
  std::vector<glm::vec3> flat_normals;
  std::vector<std::uint32_t> corner_faces;
  std::vector<std::uint32_t> triangles;  // three corner ids each
  std::vector<glm::vec3> vertex_positions;
  std::vector<std::uint32_t> segments;  // two vertex ids each
  SegmentRange all_edges, mobius_edges, border_edges;
  std::vector<std::array<std::uint8_t, 4>> face_colors;
  std::uint32_t num_faces = 0;
  BoundingBox bounds;
};

MeshDisplayData build_display_data(const Mesh& mesh);

}  // namespace nome::render

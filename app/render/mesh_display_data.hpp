#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/mesh/buffer.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "render/bounding_box.hpp"

namespace nome::render {

// A range of segments in DisplayTopology::segments.
struct SegmentRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

// What the GPU draws of a mesh that stays while only its vertices move: one GL vertex per face corner
// naming its mesh vertex (with the corner's orientation sign, so that the smooth normal turns into the
// face's own orientation: Möbius-aware) and its face, the kernel's triangles over the corners, and the
// mesh's real edges as segments over its vertices: all edges, the Möbius ones, the border ones.
struct DisplayTopology {
  // Vertex id, with corner_sign_bit set where the corner's sign is negative.
  std::vector<std::uint32_t> corner_vertices;
  std::vector<std::uint32_t> corner_faces;
  std::vector<std::uint32_t> triangles;  // three corner ids each
  std::vector<std::uint32_t> segments;   // two vertex ids each
  SegmentRange all_edges, mobius_edges, border_edges;
  std::uint32_t num_faces = 0;
  std::uint32_t num_vertices = 0;
};
inline constexpr std::uint32_t corner_sign_bit = 0x80000000u;

// What a slider that moves vertices changes: per vertex its position and unit normal (relative to the
// first face of its fan; zero at a pinch, where the shader takes the face's normal), per face its unit
// normal, in single precision. Buffer blocks: arrays of a million faces get huge pages, not fresh 4 KB
// pages one by one.
struct DisplayPositions {
  Buffer<glm::vec3> vertices;
  Buffer<glm::vec3> vertex_normals;
  Buffer<glm::vec3> face_normals;
  BoundingBox bounds;
};

// Everything the GPU needs of a kernel Mesh, built on the CPU (testable without GL). Results of the same
// topology share one DisplayTopology: the renderer then updates the positions and normals only. The
// positions are shared too, so that their maker can fill them again once no one else holds them.
struct MeshDisplayData {
  std::shared_ptr<const DisplayTopology> topology;
  std::shared_ptr<const DisplayPositions> positions;
  std::vector<std::array<std::uint8_t, 4>> face_colors;  // RGBA per face; alpha 0 where it has none
};

DisplayTopology build_display_topology(const Mesh& mesh);
// Fills `out` for the mesh's positions; `normals` is scratch space kept between calls (its blocks reused).
void build_display_positions(const Mesh& mesh, Normals& normals, DisplayPositions& out);
std::vector<std::array<std::uint8_t, 4>> display_face_colors(const Mesh& mesh);
MeshDisplayData build_display_data(const Mesh& mesh);

}  // namespace nome::render

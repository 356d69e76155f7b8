#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/buffer.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/packed_normal.hpp"
#include "render/bounding_box.hpp"

namespace nome::render {

// A range of segments in DisplayTopology::segments.
struct SegmentRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

// What the GPU draws of a mesh that stays while only its vertices move. One GL vertex per mesh vertex,
// shared by the triangles around it (llvmpipe shades it about once, not once per corner), plus extra
// vertices: a second one with the normal turned round where a vertex's fan crosses a Möbius edge (the
// corners of negative sign: the smooth normal follows each face's own orientation), and repeats that
// carry a face id. Each triangle ends with a vertex that carries its face id (the provoking vertex, by
// the last-vertex convention, GLES' only one: the fragment shader reads it as a flat input, for the face's
// colour, selection and normal; gl_PrimitiveID would cost llvmpipe a copy of every triangle's vertices).
// Segments: the mesh's real edges over its vertices: all edges, the Möbius ones, the border ones.
struct DisplayTopology {
  // GL vertex num_vertices + i repeats mesh vertex extra_vertices[i] & ~corner_sign_bit, its normal
  // turned round where corner_sign_bit is set.
  Buffer<std::uint32_t> extra_vertices;
  Buffer<std::uint32_t> vertex_faces;  // per GL vertex: the face of the triangles it starts
  Buffer<std::uint32_t> triangles;     // three GL vertex ids each, the face's own vertex last
  Buffer<std::uint32_t> segments;      // two vertex ids each
  SegmentRange all_edges, mobius_edges, border_edges;
  std::uint32_t num_faces = 0;
  std::uint32_t num_vertices = 0;

  std::uint32_t num_gl_vertices() const { return num_vertices + std::uint32_t(extra_vertices.size()); }
};
inline constexpr std::uint32_t corner_sign_bit = 0x80000000u;

// What a slider that moves vertices changes: per vertex its position and unit normal (relative to the
// first face of its fan; zero at a pinch, where the shader takes the face's normal), per face its unit
// normal; positions in single precision, normals packed in 32 bits (PackedNormal: a third of the bytes to
// write and upload); and the same for the topology's extra GL vertices (gathered here, off the thread that
// uploads them). Buffer blocks: a new topology's arrays take freed blocks the program kept, not fresh pages.
struct DisplayPositions {
  Buffer<glm::vec3> vertices;
  Buffer<PackedNormal> vertex_normals;
  Buffer<PackedNormal> face_normals;
  Buffer<glm::vec3> extra_vertices;  // per DisplayTopology::extra_vertices, its normal turned round if so
  Buffer<PackedNormal> extra_normals;
  BoundingBox bounds;
};

// Everything the GPU needs of a kernel Mesh, built on the CPU (testable without GL). Results of the same
// topology share one DisplayTopology: the renderer then updates the positions and normals only. The
// positions are shared too, so that their maker can fill them again once no one else holds them.
struct MeshDisplayData {
  std::shared_ptr<const DisplayTopology> topology;
  std::shared_ptr<const DisplayPositions> positions;
  // RGBA per face, alpha 0 where it has none; empty where no face has one (a slider's tick at a million
  // faces then neither fills nor uploads a table).
  std::vector<std::array<std::uint8_t, 4>> face_colors;
};

// On up to `threads` threads where the work splits.
DisplayTopology build_display_topology(const Mesh& mesh, int threads = 1);
// Where DisplayPositions' face and vertex normals come from: computed from the mesh (compute_packed_normals),
// or already in `out` (the kernel's, e.g. Pipeline::display_normals).
enum class DisplayNormals { computed, given };
// Fills `out` for the mesh's positions and the GL vertices of `topology` (the mesh's), on up to `threads`
// threads (into its arrays' blocks).
void build_display_positions(const Mesh& mesh, const DisplayTopology& topology, DisplayPositions& out,
                             int threads = 1, DisplayNormals normals = DisplayNormals::computed);
// The mesh's face colours as RGBA bytes, empty when it has none.
std::vector<std::array<std::uint8_t, 4>> display_face_colors(const Mesh& mesh);
MeshDisplayData build_display_data(const Mesh& mesh);

}  // namespace nome::render

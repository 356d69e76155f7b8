#pragma once

#include <span>

#include "nome/mesh/types.hpp"

namespace nome {

// The last level of a subdivision as a writer needs it: positions and quads, without the edges, fans and
// signs of a Mesh (about 40 bytes a face instead of about 180). The spans belong to whoever made it (a
// Refinement, through Pipeline::run_quads) and stay valid until that changes.
struct QuadSurface {
  std::span<const Vec3> positions;
  std::span<const Index> quad_vertices;  // quad f has corners [4f .. 4f+3], in its orientation

  Index num_vertices() const { return Index(positions.size()); }
  Index num_faces() const { return Index(quad_vertices.size() / 4); }
  Index face_degree(Index) const { return 4; }
  std::span<const Index> face_vertices(Index f) const { return quad_vertices.subspan(4 * size_t(f), 4); }
  const Vec3& position(Index v) const { return positions[v]; }
};

}  // namespace nome

#pragma once

#include <span>

#include "nome/mesh/mesh.hpp"

namespace nome {

// What the writers read of any surface (a QuadSurface and an OffsetSurface have it already): positions,
// and each face's vertices in its orientation.
struct MeshSurface {
  const Mesh& mesh;

  explicit MeshSurface(const Mesh& m) : mesh(m) {}
  Index num_vertices() const { return mesh.num_vertices(); }
  Index num_faces() const { return mesh.num_faces(); }
  Index face_degree(Index f) const { return mesh.face_degree(f); }
  std::span<const Index> face_vertices(Index f) const { return mesh.face_vertices(f); }
  const Vec3& position(Index v) const { return mesh.position(v); }
};

}  // namespace nome

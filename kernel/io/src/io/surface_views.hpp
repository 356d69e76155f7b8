#pragma once

#include <span>
#include <vector>

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

// The number each vertex is written with: the copies of a vertex split into one per fan
// (Mesh::vertex_origins) share their first copy's, the others follow in order. Empty when the mesh has no
// split vertex: vertex v is then number v.
inline std::vector<Index> written_vertex_numbers(const Mesh& mesh) {
  const std::vector<Index>& origins = mesh.vertex_origins();
  std::vector<Index> number(origins.size());
  Index next = 0;
  for (Index v = 0; v < origins.size(); ++v) number[v] = origins[v] == v ? next++ : number[origins[v]];
  return number;
}

// A mesh with split vertices as its writers show it: each split vertex once (written_vertex_numbers).
struct JoinedMeshSurface {
  const Mesh& mesh;
  std::vector<Index> number;   // mesh vertex -> written vertex
  std::vector<Index> written;  // written vertex -> its first mesh vertex
  mutable std::vector<Index> face;

  explicit JoinedMeshSurface(const Mesh& m) : mesh(m), number(written_vertex_numbers(m)) {
    for (Index v = 0; v < number.size(); ++v)
      if (number[v] == written.size()) written.push_back(v);
  }
  Index num_vertices() const { return Index(written.size()); }
  Index num_faces() const { return mesh.num_faces(); }
  Index face_degree(Index f) const { return mesh.face_degree(f); }
  std::span<const Index> face_vertices(Index f) const {
    face.clear();
    for (Index v : mesh.face_vertices(f)) face.push_back(number[v]);
    return face;
  }
  const Vec3& position(Index v) const { return mesh.position(written[v]); }
};

}  // namespace nome

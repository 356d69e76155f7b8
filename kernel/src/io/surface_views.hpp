#pragma once

#include <span>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// What the writers read of any surface (a QuadSurface has it already): positions, and each face's
// vertices in its orientation.
struct MeshSurface {
  const Mesh& mesh;
  std::span<const Vec3> positions;

  explicit MeshSurface(const Mesh& m) : mesh(m), positions(m.positions()) {}
  Index num_vertices() const { return mesh.num_vertices(); }
  Index num_faces() const { return mesh.num_faces(); }
  Index face_degree(Index f) const { return mesh.face_degree(f); }
  std::span<const Index> face_vertices(Index f) const { return mesh.face_vertices(f); }
  const Vec3& position(Index v) const { return positions[v]; }
};

struct SoupSurface {
  const PolygonSoup& soup;
  std::span<const Vec3> positions;

  explicit SoupSurface(const PolygonSoup& s) : soup(s), positions(s.positions) {}
  Index num_vertices() const { return soup.num_vertices(); }
  Index num_faces() const { return soup.num_faces(); }
  Index face_degree(Index f) const { return soup.face_offsets[f + 1] - soup.face_offsets[f]; }
  std::span<const Index> face_vertices(Index f) const {
    return {soup.face_vertices.data() + soup.face_offsets[f], face_degree(f)};
  }
  const Vec3& position(Index v) const { return positions[v]; }
};

}  // namespace nome

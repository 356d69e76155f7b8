#pragma once

#include <span>
#include <vector>

#include "nome/buffer.hpp"
#include "nome/mesh/mesh.hpp"

namespace nome {

// The solid that offset() makes, as a writer reads it: the positions and polygons of
// offset(mesh, normals, {distance}), numbered alike and bit for bit the same, computed from the
// surface and its vertex normals as they are read instead of stored. Exporting a solid then touches no
// memory for it, where the stored polygons were 44 bytes a face of fresh pages, which cost more than
// their arithmetic on these machines. Reads `mesh`, which must outlive it; keeps the vertex normals.
class OffsetSurface {
 public:
  // Throws InvalidInputError when the distance is not positive and finite, or the normals are not one
  // per vertex of `mesh`.
  OffsetSurface(const Mesh& mesh, Buffer<Vec3> vertex_normals, double distance);

  Index num_vertices() const { return 2 * num_sources_; }
  // The positive copies of the faces, then the negative copies, then one quad per border edge.
  Index num_faces() const { return 2 * mesh_->num_faces() + Index(border_edges_.size()); }
  std::size_t num_corners() const { return 2 * std::size_t(mesh_->num_corners()) + 4 * border_edges_.size(); }
  Index face_degree(Index f) const;
  // Valid until the next call.
  std::span<const Index> face_vertices(Index f) const;
  Vec3 position(Index v) const;

 private:
  // Input vertex v on side 0 (v+) or 1 (v-) is output vertex 2 rank(v) + side.
  Index out_vertex(Index v, int side) const { return 2 * (rank_.empty() ? v : rank_[v]) + Index(side); }
  // The side of corner c's vertex in the positive copy of its face.
  int positive_side(Index c) const { return mesh_->corner_sign(c) > 0 ? 0 : 1; }

  const Mesh* mesh_;
  Buffer<Vec3> normals_;
  double distance_;
  Index num_sources_ = 0;            // vertices with faces
  std::vector<Index> rank_;          // empty when every vertex has faces (the identity)
  std::vector<Index> sources_;       // the input vertex of each output pair; empty likewise
  std::vector<Index> border_edges_;  // in loop order
  mutable std::vector<Index> face_;
};

}  // namespace nome

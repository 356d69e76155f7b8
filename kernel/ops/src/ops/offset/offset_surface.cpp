#include "nome/ops/offset_surface.hpp"

#include <string>

#include "nome/error.hpp"
#include "ops/offset/offset_input.hpp"

namespace nome {

OffsetSurface::OffsetSurface(const Mesh& mesh, Buffer<Vec3> vertex_normals, double distance)
    : mesh_(&mesh), normals_(std::move(vertex_normals)), distance_(distance) {
  check_offset_distance("OffsetSurface", distance);
  if (normals_.size() != mesh.num_vertices())
    throw InvalidInputError("OffsetSurface: expected " + std::to_string(mesh.num_vertices()) +
                            " vertex normals, got " + std::to_string(normals_.size()));
  rank_ = vertex_ranks(mesh, num_sources_);
  if (!rank_.empty()) {
    sources_.resize(num_sources_);
    for (Index v = 0; v < mesh.num_vertices(); ++v)
      if (rank_[v] != no_index) sources_[rank_[v]] = v;
  }
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l)
    for (Index e : mesh.loop_edges(l)) border_edges_.push_back(e);
}

Index OffsetSurface::face_degree(Index f) const {
  const Index nf = mesh_->num_faces();
  return f < 2 * nf ? mesh_->face_degree(f < nf ? f : f - nf) : 4;
}

std::span<const Index> OffsetSurface::face_vertices(Index f) const {
  const Mesh& m = *mesh_;
  const Index nf = m.num_faces();
  face_.clear();
  if (f < 2 * nf) {
    // The negative copy is the positive one reversed from its first corner: corner k of it holds the
    // vertex of corner (n - k) % n, on the other side.
    const bool is_negative = f >= nf;
    const Index g = is_negative ? f - nf : f, b = m.face_first_corner(g), n = m.face_degree(g);
    for (Index k = 0; k < n; ++k) {
      const Index c = b + (is_negative && k > 0 ? n - k : k);
      const int side = positive_side(c);
      face_.push_back(out_vertex(m.corner_vertex(c), is_negative ? 1 - side : side));
    }
    return face_;
  }
  // Border quad (b+, a+, a-, b-) for border edge a -> b of its face: it runs against both copies.
  const Edge& edge = m.edge(border_edges_[f - 2 * nf]);
  const Index ca = edge.corners[0], cb = m.next_corner(ca);
  const Index va = edge.vertices[0], vb = edge.vertices[1];
  face_ = {out_vertex(vb, positive_side(cb)), out_vertex(va, positive_side(ca)),
           out_vertex(va, 1 - positive_side(ca)), out_vertex(vb, 1 - positive_side(cb))};
  return face_;
}

Vec3 OffsetSurface::position(Index v) const {
  const Index source = sources_.empty() ? v / 2 : sources_[v / 2];
  const Vec3 shift = distance_ * normals_[source];
  return v % 2 == 0 ? mesh_->position(source) + shift : mesh_->position(source) - shift;
}

}  // namespace nome

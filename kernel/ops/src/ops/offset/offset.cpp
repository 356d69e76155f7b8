#include "nome/ops/offset.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <string>

#include "nome/error.hpp"
#include "nome/mesh/face_orientation.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/thread_support.hpp"
#include "ops/offset/offset_input.hpp"
#include "support/parallel_for.hpp"

namespace nome {
namespace {

// v+ and v- of each vertex that has faces, in vertex order; on up to `threads` threads when every vertex
// has faces (vertex v's pair is then at 2v).
void write_offset_positions(const Mesh& mesh, const Normals& normals, double distance, std::span<Vec3> out,
                            int threads = 1) {
  if (out.size() == 2 * std::size_t(mesh.num_vertices())) {
    parallel_for(mesh.num_vertices(), threads, [&](Index begin, Index end) {
      for (Index v = begin; v < end; ++v) {
        const Vec3 shift = distance * normals.vertices[v];
        out[2 * std::size_t(v)] = mesh.position(v) + shift;
        out[2 * std::size_t(v) + 1] = mesh.position(v) - shift;
      }
    });
    return;
  }
  Index next = 0;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.is_isolated_vertex(v)) continue;
    const Vec3 shift = distance * normals.vertices[v];
    out[next++] = mesh.position(v) + shift;
    out[next++] = mesh.position(v) - shift;
  }
}

// Where a corner sits in its face. Polygons of any degree read it from the mesh: two dependent random
// reads per corner (its face, then the face's first corner). A mesh of quads only, which is what
// subdivision gives and so the usual input, computes it: face c / 4, first corner c & ~3.
struct PolygonCorners {
  const Mesh& m;
  Index face(Index c) const { return m.corner_face(c); }
  Index first(Index f) const { return m.face_first_corner(f); }
  Index degree(Index f) const { return m.face_degree(f); }
  Index next(Index c) const { return m.next_corner(c); }
};

struct QuadCorners {
  Index face(Index c) const { return c >> 2; }
  Index first(Index f) const { return 4 * f; }
  Index degree(Index) const { return 4; }
  Index next(Index c) const { return (c & ~Index(3)) | ((c + 1) & 3); }
};

// Builds the offset's arrays. Input vertex v on side `side` (0: v+, 1: v-) is output vertex
// 2 rank(v) + side. The corner with sign s sits on side 0 in the positive copy when s = +1.
template <class Corners>
class OffsetBuilder {
 public:
  OffsetBuilder(const Mesh& m, Corners corners)
      : m_(m), corners_(corners), nf_(m.num_faces()), nc_(m.num_corners()), ne_(m.num_edges()) {
    rank_ = vertex_ranks(m, nv_out_);
    ranks_are_identity_ = nv_out_ == m.num_vertices();
    signs_all_positive_ =
        std::all_of(m.corner_signs().begin(), m.corner_signs().end(), [](signed char s) { return s > 0; });
    // Border bookkeeping: each border edge's loop position (its quad) and each border vertex's loop
    // position (its side edge, joining v+ and v-).
    if (m.num_boundary_loops() == 0) return;
    loop_of_edge_.assign(ne_, no_index);
    loop_of_vertex_.assign(m.num_vertices(), no_index);
    for (Index l = 0; l < m.num_boundary_loops(); ++l) {
      const auto es = m.loop_edges(l);
      const auto vs = m.loop_vertices(l);
      for (size_t i = 0; i < es.size(); ++i, ++num_border_) {
        loop_of_edge_[es[i]] = num_border_;
        loop_of_vertex_[vs[i]] = num_border_;
      }
    }
  }

  // Into the blocks of `a` (from take_arrays, or fresh). The fans and the components fill arrays of their
  // own: with a second thread they are built beside the rest (each phase reads only the input mesh).
  Mesh build(const Normals& normals, double distance, MeshArrays a, int threads) const {
    auto fans_and_components = [&] {
      fans(a);
      components(a);
    };
    // The future waits for the helper even when this thread throws, and passes on the helper's exception.
    std::future<void> helper;
    if (threads > 1 && nf_ >= min_items_a_thread && can_start_threads())
      helper = std::async(std::launch::async, fans_and_components);
    resize_for_overwrite(a.positions, 2 * size_t(nv_out_));
    write_offset_positions(m_, normals, distance, a.positions);
    faces(a.face_offsets, a.corner_vertices);
    edges(a);
    if (!m_.face_attributes().empty())
      a.face_attributes = carried(m_.face_attributes(), offset_face_origins(m_));
    if (helper.valid())
      helper.get();
    else
      fans_and_components();
    return assemble_mesh(std::move(a));
  }

 private:
  // Without isolated vertices (the usual case) the ranks are the identity: no lookup.
  Index out_vertex(Index v, int side) const { return 2 * (ranks_are_identity_ ? v : rank_[v]) + Index(side); }
  bool has_output(Index v) const { return ranks_are_identity_ || rank_[v] != no_index; }
  // The side of v used by corner c's positive copy.
  int positive_side(Index c) const { return signs_all_positive_ || m_.corner_sign(c) > 0 ? 0 : 1; }
  // Negative copy of face f: corner i holds the vertex of parent corner (n - i) % n, and its edge is the
  // parent edge of corner n - 1 - i; so parent corner c's vertex sits at negative corner (n - local) % n.
  Index negative_corner_at_vertex(Index c) const {
    const Index b = corners_.first(corners_.face(c));
    return nc_ + (c == b ? b : 2 * b + corners_.degree(corners_.face(c)) - c);
  }
  Index negative_corner_along_edge(Index c) const {
    const Index b = corners_.first(corners_.face(c));
    return nc_ + 2 * b + corners_.degree(corners_.face(c)) - 1 - c;
  }
  Index ribbon_corner(Index j, int k) const { return 2 * nc_ + 4 * j + Index(k); }
  // The corner of the first face of border edge e at its vertex v.
  Index first_face_corner_at(Index e, Index v) const {
    const Edge& edge = m_.edge(e);
    return edge.vertices[0] == v ? edge.corners[0] : corners_.next(edge.corners[0]);
  }

  void faces(Buffer<Index>& face_offsets, Buffer<Index>& corner_vertices) const {
    resize_for_overwrite(face_offsets, 2 * size_t(nf_) + num_border_ + 1);
    for (Index f = 0; f <= nf_; ++f) {
      face_offsets[f] = m_.face_offsets()[f];
      face_offsets[nf_ + f] = nc_ + m_.face_offsets()[f];
    }
    for (Index j = 0; j <= num_border_; ++j) face_offsets[2 * nf_ + j] = 2 * nc_ + 4 * j;
    resize_for_overwrite(corner_vertices, 2 * size_t(nc_) + 4 * size_t(num_border_));
    // Face by face, so that the negative copy's reversal needs no division (negative_corner_at_vertex).
    for (Index f = 0; f < nf_; ++f) {
      const Index b = corners_.first(f), n = corners_.degree(f);
      for (Index i = 0; i < n; ++i) {
        const Index v = m_.corner_vertex(b + i);
        const int side = positive_side(b + i);
        corner_vertices[b + i] = out_vertex(v, side);
        corner_vertices[nc_ + b + (i == 0 ? 0 : n - i)] = out_vertex(v, 1 - side);
      }
    }
    // Border quad (b+, a+, a-, b-) for border edge a -> b of its face: it runs against both copies.
    for (Index l = 0; l < m_.num_boundary_loops(); ++l)
      for (Index e : m_.loop_edges(l)) {
        const Edge& edge = m_.edge(e);
        const Index j = loop_of_edge_[e], ca = edge.corners[0], cb = corners_.next(ca);
        const Index va = edge.vertices[0], vb = edge.vertices[1];
        Index* q = corner_vertices.data() + ribbon_corner(j, 0);
        q[0] = out_vertex(vb, positive_side(cb));
        q[1] = out_vertex(va, positive_side(ca));
        q[2] = out_vertex(va, 1 - positive_side(ca));
        q[3] = out_vertex(vb, 1 - positive_side(cb));
      }
  }

  // Input edge e gives edge 2e (in the positive copy of its first face) and 2e+1 (in the negative copy);
  // border vertex at loop position j gives the side edge 2E + j.
  void edges(MeshArrays& a) const {
    resize_for_overwrite(a.edges, 2 * size_t(ne_) + num_border_);  // each record default-initialized in place
    resize_for_overwrite(a.corner_edges, a.corner_vertices.size());
    a.corner_signs.assign(a.corner_vertices.size(), 1);
    for (Index e = 0; e < ne_; ++e) {
      const Edge& in = m_.edge(e);
      Edge& plus = a.edges[2 * e];
      Edge& minus = a.edges[2 * e + 1];
      const Index ca = in.corners[0];
      const int sa = positive_side(ca), sb = positive_side(corners_.next(ca));
      plus.vertices = {out_vertex(in.vertices[0], sa), out_vertex(in.vertices[1], sb)};
      minus.vertices = {out_vertex(in.vertices[1], 1 - sb), out_vertex(in.vertices[0], 1 - sa)};
      plus.corners[0] = ca;
      minus.corners[0] = negative_corner_along_edge(ca);
      // Faces from the input edge's own record (a lookup per corner would read at random).
      plus.faces[0] = in.faces[0];
      minus.faces[0] = nf_ + in.faces[0];
      if (in.is_boundary()) {
        const Index j = loop_of_edge_[e];
        plus.corners[1] = ribbon_corner(j, 0);
        minus.corners[1] = ribbon_corner(j, 2);
        plus.faces[1] = minus.faces[1] = 2 * nf_ + j;
      } else if (in.is_mobius) {
        plus.corners[1] = negative_corner_along_edge(in.corners[1]);
        minus.corners[1] = in.corners[1];
        plus.faces[1] = nf_ + in.faces[1];
        minus.faces[1] = in.faces[1];
      } else {
        plus.corners[1] = in.corners[1];
        minus.corners[1] = negative_corner_along_edge(in.corners[1]);
        plus.faces[1] = in.faces[1];
        minus.faces[1] = nf_ + in.faces[1];
      }
      plus.is_sharp = minus.is_sharp = in.is_sharp;
      for (Edge* out : {&plus, &minus})
        a.corner_edges[out->corners[0]] = a.corner_edges[out->corners[1]] = Index(out - a.edges.data());
    }
    // Side edges: the border quad of loop position j has a's side at corners 1 -> 2 and b's at 3 -> 0.
    for (Index l = 0; l < m_.num_boundary_loops(); ++l)
      for (Index e : m_.loop_edges(l)) {
        const Index j = loop_of_edge_[e];
        for (int end = 0; end < 2; ++end) {
          const Index v = m_.edge(e).vertices[end];
          const Index side_edge = 2 * ne_ + loop_of_vertex_[v];
          const Index corner = ribbon_corner(j, end == 0 ? 1 : 3);
          a.corner_edges[corner] = side_edge;
          Edge& out = a.edges[side_edge];
          if (loop_of_vertex_[v] ==
              j) {  // the loop starts this edge at v: this quad is the edge's first face
            out.vertices = {
                a.corner_vertices[corner],
                a.corner_vertices[corner == ribbon_corner(j, 1) ? ribbon_corner(j, 2) : ribbon_corner(j, 0)]};
            out.corners[0] = corner;
          } else {
            out.corners[1] = corner;
          }
        }
      }
    for (Index e = 2 * ne_; e < a.edges.size(); ++e)
      a.edges[e].faces = {ribbon_face(a.edges[e].corners[0]), ribbon_face(a.edges[e].corners[1])};
  }

  // Components without a walk over the (twice as large) output: a closed component that orients
  // consistently has a double cover in two pieces, the copies on each side; any other gives one piece.
  void components(MeshArrays& a) const {
    FaceOrientation orientation;
    if (signs_all_positive_) {
      orientation.face_signs.assign(nf_, 1);
      orientation.component_orientable.assign(m_.num_components(), 1);
    } else {
      orientation = face_orientation(m_);
    }
    std::vector<char> splits = orientation.component_orientable;
    for (Index l = 0; l < m_.num_boundary_loops(); ++l)
      splits[m_.face_component(m_.edge(m_.loop_edges(l).front()).faces[0])] = 0;
    std::vector<Index> first_output(m_.num_components(), no_index);
    a.num_components = 0;
    for (Index k = 0; k < m_.num_components(); ++k) {
      first_output[k] = a.num_components;
      a.num_components += splits[k] ? 2 : 1;
    }
    resize_for_overwrite(a.face_components, 2 * size_t(nf_) + num_border_);
    for (Index f = 0; f < nf_; ++f) {
      const Index k = m_.face_component(f);
      const Index other = splits[k] ? 1 : 0;
      const bool positive = orientation.face_signs[f] > 0;
      a.face_components[f] = first_output[k] + (positive ? 0 : other);
      a.face_components[nf_ + f] = first_output[k] + (positive ? other : 0);
    }
    for (Index l = 0; l < m_.num_boundary_loops(); ++l)
      for (Index e : m_.loop_edges(l))
        a.face_components[2 * nf_ + loop_of_edge_[e]] = first_output[m_.face_component(m_.edge(e).faces[0])];
  }

  Index ribbon_face(Index c) const { return 2 * nf_ + (c - 2 * nc_) / 4; }

  // Output vertex (v, side): the copies of v's fan faces that hold it, in fan order; at a border vertex
  // the fan closes through the last border quad, the side edge and the first border quad.
  void fans(MeshArrays& a) const {
    const Index nv = m_.num_vertices();
    // A running sum in v order (which is output vertex order): every offset written once, no sum that
    // reloads the value just stored. The solid is closed, so each fan has as many edges as corners.
    resize_for_overwrite(a.fan_corner_offsets, 2 * size_t(nv_out_) + 1);
    a.fan_corner_offsets[0] = 0;
    Index total = 0;
    for (Index v = 0; v < nv; ++v) {
      if (!has_output(v)) continue;
      const Index k = Index(m_.vertex_corners(v).size()) + (m_.is_boundary_vertex(v) ? 2 : 0);
      a.fan_corner_offsets[out_vertex(v, 0) + 1] = total += k;
      a.fan_corner_offsets[out_vertex(v, 1) + 1] = total += k;
    }
    a.fan_edge_offsets.assign(a.fan_corner_offsets.begin(), a.fan_corner_offsets.end());
    resize_for_overwrite(a.fan_corners, a.fan_corner_offsets.back());
    resize_for_overwrite(a.fan_edges, a.fan_edge_offsets.back());
    for (Index v = 0; v < nv; ++v) {
      if (!has_output(v)) continue;
      const auto corners = m_.vertex_corners(v);
      const auto edges = m_.vertex_edges(v);
      // Both sides at once (each element's side is looked up once): v+ and v- are consecutive.
      const Index w = out_vertex(v, 0);
      Index* fc[2] = {a.fan_corners.data() + a.fan_corner_offsets[w],
                      a.fan_corners.data() + a.fan_corner_offsets[w + 1]};
      Index* fe[2] = {a.fan_edges.data() + a.fan_edge_offsets[w],
                      a.fan_edges.data() + a.fan_edge_offsets[w + 1]};
      for (size_t i = 0; i < corners.size(); ++i) {
        const Index c = corners[i];
        const int side = positive_side(c);
        fc[side][i] = c;
        fc[1 - side][i] = negative_corner_at_vertex(c);
      }
      // Fan edge i lies between corners i-1 and i (cyclically inside, only one of them at a border end).
      // Unless it is a Möbius edge their signs agree and give its side; only then is its record read.
      const size_t k = corners.size();
      const bool border = m_.is_boundary_vertex(v);
      for (size_t i = 0; i < edges.size(); ++i) {
        const Index e = edges[i];
        const Index before = corners[i == 0 ? (border ? 0 : k - 1) : i - 1];
        const Index after = corners[i == k ? k - 1 : i];
        const int side = positive_side(before) == positive_side(after)
                             ? positive_side(after)
                             : positive_side(first_face_corner_at(e, v));
        fe[side][i] = 2 * e;
        fe[1 - side][i] = 2 * e + 1;
      }
      if (!border) continue;
      for (int side = 0; side < 2; ++side) {
        fc[side][k] = ribbon_corner_at(edges.back(), v, side);
        fc[side][k + 1] = ribbon_corner_at(edges.front(), v, side);
        fe[side][k + 1] = 2 * ne_ + loop_of_vertex_[v];
      }
    }
  }

  // The corner of border edge e's quad (b+, a+, a-, b-) at output vertex (v, side).
  Index ribbon_corner_at(Index e, Index v, int side) const {
    const Index j = loop_of_edge_[e];
    const bool positive = positive_side(first_face_corner_at(e, v)) == side;
    if (m_.edge(e).vertices[0] == v) return ribbon_corner(j, positive ? 1 : 2);
    return ribbon_corner(j, positive ? 0 : 3);
  }

  const Mesh& m_;
  Corners corners_;
  Index nf_, nc_, ne_;
  Index nv_out_ = 0, num_border_ = 0;
  bool ranks_are_identity_ = false;
  // No Möbius edge anywhere (any consistently oriented surface, the usual input) makes every corner sign
  // +1: then no sign is read, where the fans and edges would read them at random, and no orientation
  // needs finding for the components.
  bool signs_all_positive_ = false;
  std::vector<Index> rank_, loop_of_edge_, loop_of_vertex_;
};

// The builder with the corner layout of `mesh`.
template <class Work>
auto with_offset_builder(const Mesh& mesh, const Work& work) {
  if (mesh.is_quad_mesh()) return work(OffsetBuilder<QuadCorners>(mesh, QuadCorners{}));
  return work(OffsetBuilder<PolygonCorners>(mesh, PolygonCorners{mesh}));
}

}  // namespace

void check_offset_distance(const char* who, double distance) {
  if (!(distance > 0.0) || !std::isfinite(distance))
    throw InvalidInputError(std::string(who) + ": the offset distance must be positive and finite, got " +
                            std::to_string(distance));
}

std::vector<Index> vertex_ranks(const Mesh& mesh, Index& count) {
  // A count over the fan offsets (it vectorises): each slider tick's offset_positions asks again.
  const Index* fans = mesh.fan_corner_offsets().data();
  count = 0;
  for (Index v = 0; v < mesh.num_vertices(); ++v) count += fans[v] != fans[v + 1] ? 1 : 0;
  if (count == mesh.num_vertices()) return {};
  std::vector<Index> rank(mesh.num_vertices(), no_index);
  count = 0;
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (!mesh.is_isolated_vertex(v)) rank[v] = count++;
  return rank;
}

ElementOrigins offset_face_origins(const Mesh& mesh) {
  ElementOrigins origins;
  origins.parents.reserve(2 * size_t(mesh.num_faces()));
  for (int copy = 0; copy < 2; ++copy)
    for (Index f = 0; f < mesh.num_faces(); ++f) origins.parents.push_back(f);
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l)
    for (Index e : mesh.loop_edges(l)) origins.parents.push_back(mesh.edge(e).faces[0]);
  return origins;
}

Mesh offset(const Mesh& mesh, const OffsetOptions& options) {
  return offset(mesh, compute_normals(mesh), options);
}

Mesh offset(const Mesh& mesh, const Normals& normals, const OffsetOptions& options) {
  check_offset_distance("offset", options.distance);
  Mesh solid = with_offset_builder(mesh, [&](const auto& builder) {
    return builder.build(normals, options.distance, MeshArrays(), options.threads);
  });
  if (options.subdivision_levels == 0) return solid;
  return subdivide(solid, {.levels = options.subdivision_levels, .rule = options.rule});
}

void offset_into(const Mesh& mesh, const Normals& normals, double distance, Mesh& solid, int threads) {
  check_offset_distance("offset_into", distance);
  MeshArrays storage = take_arrays(std::move(solid));
  solid = with_offset_builder(mesh, [&](const auto& builder) {
    return builder.build(normals, distance, std::move(storage), threads);
  });
}

void offset_positions(const Mesh& mesh, double distance, std::span<Vec3> out) {
  offset_positions(mesh, compute_normals(mesh), distance, out);
}

void offset_positions(const Mesh& mesh, const Normals& normals, double distance, std::span<Vec3> out,
                      int threads) {
  check_offset_distance("offset_positions", distance);
  Index count = 0;
  vertex_ranks(mesh, count);
  if (out.size() != 2 * size_t(count))
    throw InvalidInputError("offset_positions: output holds " + std::to_string(out.size()) +
                            " positions, the offset has " + std::to_string(2 * size_t(count)));
  write_offset_positions(mesh, normals, distance, out, threads);
}

}  // namespace nome

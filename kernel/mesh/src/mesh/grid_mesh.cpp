#include "mesh/grid_mesh.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <utility>
#include <vector>

namespace nome {
namespace {

// Each edge of the layout has a slot that holds its number (and the vertex its first side runs from) once a
// face has made it; a corner whose slot is filled is the edge's second side, and by the layout its last.
// Slots are kept for the rings and rails in use only (a band's near and far ring, its rails, ring 0 for the
// join and the begin cap), so they stay in cache.
class GridWalk {
  struct Slot {
    Index edge = no_index;
    Index from = no_index;
  };

 public:
  GridWalk(MeshArrays& m, const SoupGrid& g)
      : m_(m),
        face_offsets_(m.face_offsets.data()),
        corner_vertices_(m.corner_vertices.data()),
        faces_(Index(m.face_offsets.size() - 1)),
        g_(g),
        points_(g.ring_points),
        cells_(g.is_ring_closed ? g.ring_points : g.ring_points - 1),
        bands_(g.join.empty() ? g.rings - 1 : g.rings),
        near_ring_(cells_),
        far_ring_(cells_),
        rails_(points_) {}

  bool run() {
    resize_for_overwrite(m_.corner_edges, m_.corner_vertices.size());  // every corner is written
    corner_edges_ = m_.corner_edges.data();
    m_.edges.clear();
    m_.edges.reserve(m_.corner_vertices.size() / 2 + 2);
    for (Index i = 0; i < bands_; ++i) {
      std::fill(rails_.begin(), rails_.end(), Slot());
      for (Index j = 0; j < cells_; ++j)
        if (!add_cell(i, j)) return false;
      if (i == 0) ring_zero_ = near_ring_;
      near_ring_.swap(far_ring_);
      std::fill(far_ring_.begin(), far_ring_.end(), Slot());
    }
    if (g_.has_begin_cap && !add_cap(0, ring_zero_, true)) return false;
    if (g_.has_end_cap && !add_cap(g_.rings - 1, near_ring_, false)) return false;
    return face_ == faces_;
  }

 private:
  Index vertex(Index i, Index j) const { return i * points_ + j; }
  Index next(Index j) const { return j + 1 == points_ ? 0 : j + 1; }
  bool is_join(Index band) const { return !g_.join.empty() && band == g_.rings - 1; }
  // Band i's far ring: ring i + 1, or for the join band ring 0 through the join.
  Index far_vertex(Index i, Index j) const { return is_join(i) ? vertex(0, g_.join[j]) : vertex(i + 1, j); }
  // The slot of the far ring's edge from point j to point next(j); null where the join does not keep them
  // adjacent.
  Slot* far_ring_slot(Index i, Index j) {
    if (!is_join(i)) return &far_ring_[j];
    const Index p = g_.join[j], q = g_.join[next(j)];
    if (next(p) == q && p < cells_) return &ring_zero_[p];
    if (next(q) == p && q < cells_) return &ring_zero_[q];
    return nullptr;
  }

  bool add_cell(Index i, Index j) {
    const Index k = next(j);
    const Index a = vertex(i, j), b = vertex(i, k), c = far_vertex(i, k), d = far_vertex(i, j);
    Slot* far = far_ring_slot(i, j);
    if (!far) return false;
    if (!g_.is_triangles)
      return add_face(std::array{a, b, c, d}, std::array{&near_ring_[j], &rails_[k], far, &rails_[j]});
    Slot diagonal;
    return add_face(std::array{a, b, c}, std::array{&near_ring_[j], &rails_[k], &diagonal}) &&
           add_face(std::array{a, c, d}, std::array{&diagonal, far, &rails_[j]});
  }

  // Ring 0 backwards (the begin cap) or the last ring forwards (the end cap), with that ring's slots.
  bool add_cap(Index ring, std::vector<Slot>& ring_slots, bool is_begin) {
    if (points_ < 3) return false;
    std::vector<Index> vertices(points_);
    std::vector<Slot*> slots(points_);
    Slot chord;  // an open ring's cap closes it with an edge of its own
    for (Index t = 0; t < points_; ++t) {
      const Index j = is_begin ? points_ - 1 - t : t;
      vertices[t] = vertex(ring, j);
      if (t + 1 < points_)
        slots[t] = &ring_slots[is_begin ? j - 1 : j];
      else
        slots[t] = g_.is_ring_closed ? &ring_slots[points_ - 1] : &chord;
    }
    return add_face(std::span<const Index>(vertices), std::span<Slot* const>(slots));
  }

  // The next face of the soup, which must have these vertices; its corners take their slots' edges. A cell's
  // face has a fixed size, so its loops unroll; a cap's has the ring's.
  template <std::size_t N>
  bool add_face(const std::array<Index, N>& vertices, const std::array<Slot*, N>& slots) {
    const Index first = next_face_first_corner(std::span<const Index, N>(vertices));
    if (first == no_index) return false;
    [&]<std::size_t... t>(std::index_sequence<t...>) {
      (take_edge(first + Index(t), vertices[t], vertices[(t + 1) % N], *slots[t]), ...);
    }
    (std::make_index_sequence<N>());
    ++face_;
    return true;
  }
  bool add_face(std::span<const Index> vertices, std::span<Slot* const> slots) {
    const Index first = next_face_first_corner(vertices), degree = Index(vertices.size());
    if (first == no_index) return false;
    for (Index t = 0; t < degree; ++t)
      take_edge(first + t, vertices[t], vertices[t + 1 == degree ? 0 : t + 1], *slots[t]);
    ++face_;
    return true;
  }
  // The next face's first corner if that face has these vertices, else no_index.
  template <std::size_t Extent>
  Index next_face_first_corner(std::span<const Index, Extent> vertices) const {
    if (face_ >= faces_ || face_offsets_[face_ + 1] - face_offsets_[face_] != vertices.size())
      return no_index;
    const Index first = face_offsets_[face_];
    for (std::size_t t = 0; t < vertices.size(); ++t)
      if (corner_vertices_[first + t] != vertices[t]) return no_index;
    return first;
  }
  // Corner c (from -> to) of the current face takes its slot's edge, a new one if the slot is empty.
  void take_edge(Index c, Index from, Index to, Slot& slot) {
    if (slot.edge == no_index) {
      slot = {edge_count_++, from};
      m_.edges.push_back(Edge{{from, to}, {face_, no_index}, {c, no_index}});
    } else {
      Edge& edge = m_.edges[slot.edge];
      edge.faces[1] = face_;
      edge.corners[1] = c;
      edge.is_mobius = from == slot.from;
    }
    corner_edges_[c] = slot.edge;
  }

  MeshArrays& m_;
  // m_'s arrays that the walk reads and writes, as plain pointers: stores to the edges do not make the
  // compiler load them again.
  const Index* face_offsets_;
  const Index* corner_vertices_;
  Index* corner_edges_ = nullptr;
  Index edge_count_ = 0;
  Index faces_;
  const SoupGrid& g_;
  Index points_, cells_, bands_;
  std::vector<Slot> near_ring_, far_ring_, rails_, ring_zero_;
  Index face_ = 0;
};

bool is_supported(const SoupGrid& g, Index num_vertices) {
  if (g.ring_points == 0 || g.rings * g.ring_points != num_vertices) return false;
  if (g.ring_points < (g.is_ring_closed ? 3u : 2u) || g.rings < (g.join.empty() ? 2u : 3u)) return false;
  if (!g.join.empty() && (g.join.size() != g.ring_points || g.has_begin_cap || g.has_end_cap)) return false;
  for (Index p : g.join)
    if (p >= g.ring_points) return false;
  return true;
}

}  // namespace

bool find_grid_edges(MeshArrays& m, const SoupGrid& grid) {
  if (is_supported(grid, Index(m.positions.size())) && GridWalk(m, grid).run()) return true;
  m.edges.clear();
  m.corner_edges.clear();
  return false;
}

}  // namespace nome

#pragma once

// Internal to subdivision: the elements of a refined level grouped by the base face they descend from (a
// tile). Children are numbered arithmetically (see Refinement), so a tile is a few index ranges per kind
// of element, and a position pass that works tile by tile reads and writes a few tens of kilobytes at a
// time instead of sweeping the whole level once per kind of element.

#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The element counts of one level.
struct LevelCounts {
  Index faces = 0, edges = 0, corners = 0, vertices = 0;
};

// The counts of the base (entry 0) and of levels 1 .. k.
std::vector<LevelCounts> level_counts(const Mesh& base, int k);

// Which base face each base edge and vertex is grouped with: the last of the faces around it, so that a tile
// visited in order finds the other sides of its edges and vertices recently visited (in the cache). Vertices
// of no face are left over (lone_vertices).
struct BaseTiles {
  // Groups the elements of `base`, in the vectors of the last build (Refinement::rebuild).
  void build(const Mesh& base);

  std::vector<Index> face_corners;  // the base's face offsets: b's corners are [face_corners[b], [b + 1])
  std::vector<Index> edge_offsets, edges, vertex_offsets, vertices;  // per base face (CSR)
  std::vector<Index> lone_vertices;
  // Whether the base has a sharp or border edge: without one, no level has a crease edge (creases are the
  // halves of creases).
  bool has_creases = true;
  std::vector<Index> owner;  // scratch: the face each edge or vertex goes with
};

// Calls faces(begin, end), edges(begin, end) and vertices(begin, end) on the index ranges of level k's
// faces, edges and vertices that descend from base faces [b, b_end) (counts: levels 0 .. k, k >= 1), in
// that order: a tile of consecutive base faces has the ranges of one, longer.
// Over all base faces and the lone vertices (tile_lone_vertex), every element is visited once.
//   level-m corners of b: [c0 << 2m, c1 << 2m), where b's corners are [c0, c1);
//   an edge born at level j inside a level-(j-1) face is 2 E(j-1) + its corner, and an edge of level m
//   has the children 2e and 2e + 1 at level m + 1: a range of 2^(k-j) edges at level k per corner;
//   a vertex of level j is F(j) + E(j) + v at level j + 1, and a face point at level j is its level-(j-1)
//   face, an edge point F(j-1) + its level-(j-1) edge.
template <class Faces, class Edges, class Vertices>
void visit_tile(const BaseTiles& t, std::span<const LevelCounts> n, Index b, Index b_end, const Faces& faces,
                const Edges& edges, const Vertices& vertices) {
  const int k = int(n.size()) - 1;
  const Index c0 = t.face_corners[b], c1 = t.face_corners[b_end];
  faces(c0 << 2 * (k - 1), c1 << 2 * (k - 1));
  // The level-m edges of b, shifted by `offset`.
  const auto edge_ranges = [&](int m, Index offset, const auto& visit) {
    for (int j = 1; j <= m; ++j) {
      const Index born = 2 * n[j - 1].edges;
      visit(offset + ((born + (c0 << 2 * (j - 1))) << (m - j)),
            offset + ((born + (c1 << 2 * (j - 1))) << (m - j)));
    }
    for (Index i = t.edge_offsets[b]; i < t.edge_offsets[b_end]; ++i)
      visit(offset + (t.edges[i] << m), offset + ((t.edges[i] + 1) << m));
  };
  edge_ranges(k, 0, edges);
  Index carry = 0;  // from a level-j vertex index to its level-k index
  for (int j = k; j >= 1; --j) {
    if (j == 1)
      vertices(carry + b, carry + b_end);
    else
      vertices(carry + (c0 << 2 * (j - 2)), carry + (c1 << 2 * (j - 2)));
    edge_ranges(j - 1, carry + n[j - 1].faces, vertices);
    carry += n[j - 1].faces + n[j - 1].edges;
  }
  for (Index i = t.vertex_offsets[b]; i < t.vertex_offsets[b_end]; ++i)
    vertices(carry + t.vertices[i], carry + t.vertices[i] + 1);
}

// Level k's index of a base vertex.
inline Index tile_lone_vertex(std::span<const LevelCounts> n, Index v) {
  for (size_t j = 0; j + 1 < n.size(); ++j) v += n[j].faces + n[j].edges;
  return v;
}

}  // namespace nome

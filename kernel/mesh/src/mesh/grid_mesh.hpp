#pragma once

#include <array>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/soup_grid.hpp"

namespace nome {

// The edges of faces laid out as `grid` says (m's corner_vertices and face_offsets filled),
// numbered and oriented as build_mesh's search would give them, found from the layout with no search.
// False, with m's edges and corner_edges cleared, when the faces do not follow the layout or the layout is
// one whose keys could name one edge twice (too few rings or points).
bool find_grid_edges(MeshArrays& m, const SoupGrid& grid);

// Whether vertex (ring i, point j) is inside a grid of quads: on neither the first nor the last ring (nor
// the border of open rings). Its four quads then lie in bands that the join does not touch, so no Möbius
// edge meets it.
inline bool is_grid_inner_vertex(const SoupGrid& grid, Index i, Index j) {
  const Index cells = grid.is_ring_closed ? grid.ring_points : grid.ring_points - 1;
  return !grid.is_triangles && i != 0 && i + 1 < grid.rings && (j != 0 || grid.is_ring_closed) && j < cells;
}

// Calls visit(f), in increasing order, for each face of a grid of quads that has a vertex not inside it
// (is_grid_inner_vertex): the first and last bands, the join, the first and last cells of open rings, caps.
template <class Visit>
void for_each_grid_border_face(const SoupGrid& grid, Index num_faces, Visit visit) {
  const Index cells = grid.is_ring_closed ? grid.ring_points : grid.ring_points - 1;
  const Index bands = grid.join.empty() ? grid.rings - 1 : grid.rings;
  for (Index b = 0; b < bands; ++b) {
    if (b == 0 || b + 2 >= grid.rings) {  // from ring 0, to the last ring, or the join to ring 0
      for (Index j = 0; j < cells; ++j) visit(b * cells + j);
    } else if (!grid.is_ring_closed) {
      visit(b * cells);
      if (cells > 1) visit(b * cells + cells - 1);
    }
  }
  for (Index f = bands * cells; f < num_faces; ++f) visit(f);
}

// The fan of an inner vertex (i, j), as build_mesh's walk finds it, once find_grid_edges found the edges:
// its four corners and four edges in fan order, all of sign +1. Inline: it runs for most vertices of a sweep.
inline void find_grid_inner_fan(const MeshArrays& m, const SoupGrid& grid, Index i, Index j,
                                std::array<Index, 4>& corners, std::array<Index, 4>& edges) {
  const Index cells = grid.is_ring_closed ? grid.ring_points : grid.ring_points - 1;
  // Quads a = (i-1, j-1), b = (i-1, j), c = (i, j-1), d = (i, j) meet at v (j-1 around the seam at j = 0).
  // The walk starts at v's first corner, in a (in b at the seam, where a comes last), and turns towards c
  // across the ring edge from v.
  const Index left = j == 0 ? cells - 1 : j - 1;
  const Index a = (i - 1) * cells + left, b = (i - 1) * cells + j, c = i * cells + left, d = i * cells + j;
  if (j != 0) {
    corners = {4 * a + 2, 4 * c + 1, 4 * d, 4 * b + 3};
    edges = {m.corner_edges[4 * a + 1], m.corner_edges[4 * a + 2], m.corner_edges[4 * c + 1],
             m.corner_edges[4 * d]};
  } else {
    corners = {4 * b + 3, 4 * a + 2, 4 * c + 1, 4 * d};
    edges = {m.corner_edges[4 * d], m.corner_edges[4 * a + 1], m.corner_edges[4 * a + 2],
             m.corner_edges[4 * c + 1]};
  }
}

}  // namespace nome

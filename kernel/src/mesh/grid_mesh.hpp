#pragma once

#include <array>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/soup_grid.hpp"

namespace nome {

// The edges of faces laid out as `grid` says (m's corner_vertices, face_offsets and corner_faces filled),
// numbered and oriented as build_mesh's search would give them, found from the layout with no search.
// False, with m's edges and corner_edges cleared, when the faces do not follow the layout or the layout is
// one whose keys could name one edge twice (too few rings or points).
bool find_grid_edges(MeshArrays& m, const SoupGrid& grid);

// The fan of vertex v = (ring i, point j), as build_mesh's walk finds it, for a vertex inside a grid of
// quads (on neither the first nor the last ring nor the rings' seam, no Möbius edge at it) whose edges
// find_grid_edges found: its four corners and four edges in fan order, all of sign +1. False for any other
// vertex (walk it). Inline: it runs for most vertices of a sweep.
inline bool find_grid_inner_fan(const MeshArrays& m, const SoupGrid& grid, Index i, Index j,
                                std::array<Index, 4>& corners, std::array<Index, 4>& edges) {
  const Index cells = grid.is_ring_closed ? grid.ring_points : grid.ring_points - 1;
  if (grid.is_triangles || i == 0 || i + 1 >= grid.rings || j == 0 || j >= cells) return false;
  // Quads (i-1, j-1), (i-1, j), (i, j-1), (i, j) meet at v; the walk starts in the first, whose corner 2 is
  // v, and turns towards (i, j-1) across the ring edge from v.
  const Index before = (i - 1) * cells + j - 1, after = i * cells + j;
  corners = {4 * before + 2, 4 * (after - 1) + 1, 4 * after, 4 * (before + 1) + 3};
  edges = {m.corner_edges[4 * before + 1], m.corner_edges[4 * before + 2],
           m.corner_edges[4 * (after - 1) + 1], m.corner_edges[4 * after]};
  return !m.edges[edges[0]].is_mobius && !m.edges[edges[1]].is_mobius && !m.edges[edges[2]].is_mobius &&
         !m.edges[edges[3]].is_mobius;
}

}  // namespace nome

#pragma once

#include <vector>

#include "nome/mesh/types.hpp"

namespace nome {

// How a generator laid out a soup whose faces are bands between rings of vertices (a sweep), so that
// build_mesh finds its edges from the layout instead of searching for them. It describes the whole soup:
//   vertices   ring i, point j is vertex i * ring_points + j;
//   faces      band i (ring i to ring i + 1), cell j (point j to point j + 1, around a closed ring), as the
//              quad (i,j) (i,j+1) (i+1,j+1) (i+1,j), or its triangles (i,j) (i,j+1) (i+1,j+1) and
//              (i,j) (i+1,j+1) (i+1,j); with `join`, one more band from the last ring to ring 0, whose
//              point j is join[j]; then the caps: ring 0 backwards, the last ring forwards.
// build_mesh checks the soup's faces against it and builds the usual way where they differ, so the mesh is
// the same with or without it.
struct SoupGrid {
  Index rings = 0;
  Index ring_points = 0;
  bool is_ring_closed = true;
  bool is_triangles = false;
  std::vector<Index> join;  // empty: the rings are not joined around
  bool has_begin_cap = false;
  bool has_end_cap = false;
  bool operator==(const SoupGrid&) const = default;
};

}  // namespace nome

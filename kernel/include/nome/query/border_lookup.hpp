#pragma once

#include <optional>
#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// Which border loop each vertex lies on, for border selection (report 7.3.2). On a 2-manifold a
// vertex lies on at most one border loop. A copy: it outlives the mesh it was built from.
class BorderLookup {
 public:
  explicit BorderLookup(const Mesh& mesh);

  bool is_on_border(Index v) const { return v < loop_of_.size() && loop_of_[v] != no_index; }
  Index loop_of(Index v) const { return loop_of_[v]; }
  // The loop's vertices in loop order.
  std::span<const Index> loop_vertices(Index loop) const {
    return {loop_vertices_.data() + loop_offsets_[loop], loop_offsets_[loop + 1] - loop_offsets_[loop]};
  }

  // The whole loop through v, starting at v (the zipper's matching point) in loop order.
  std::vector<Index> whole_loop_from(Index v) const;

  // True when a and b are neighbours on the same loop: the segment a-b needs no side vertex.
  bool are_adjacent(Index a, Index b) const;

  // The part of the loop from end a to end b that passes through `side` (both ends included, in the
  // direction a -> b). None when the three are not distinct vertices of one loop.
  std::optional<std::vector<Index>> segment(Index a, Index b, Index side) const;

 private:
  std::vector<Index> loop_offsets_{0};
  std::vector<Index> loop_vertices_;
  std::vector<Index> loop_of_;
  std::vector<Index> position_;  // index of the vertex within its loop
};

}  // namespace nome

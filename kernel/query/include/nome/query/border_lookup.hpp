#pragma once

#include <optional>
#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/query/rim_pick.hpp"

namespace nome {

// Which border loop each vertex lies on, for border selection (report 7.3.2). On a 2-manifold a
// vertex lies on at most one border loop. A copy: it outlives the mesh it was built from. Rim lines
// (report 6.3) can be added as further borders, open or closed, so that they are selected alike.
class BorderLookup {
 public:
  explicit BorderLookup(const Mesh& mesh);

  // Adds each rim line as a border whose vertex k has the id first_id + k (picking numbers rim vertices
  // after the mesh's).
  void add_rim_lines(const RimLines& rims, Index first_id);
  // Mesh borders and closed rim lines are loops; an open rim line is not.
  bool is_closed(Index loop) const { return is_closed_[loop] != 0; }

  bool is_on_border(Index v) const { return v < loop_of_.size() && loop_of_[v] != no_index; }
  Index loop_of(Index v) const { return loop_of_[v]; }
  // The loop's vertices in loop order.
  std::span<const Index> loop_vertices(Index loop) const {
    return {loop_vertices_.data() + loop_offsets_[loop], loop_offsets_[loop + 1] - loop_offsets_[loop]};
  }

  // The whole loop through v, starting at v (the zipper's matching point) in loop order; an open line
  // whole, from its first vertex.
  std::vector<Index> whole_loop_from(Index v) const;

  // True when a and b are neighbours on the same loop, or lie on the same open line: the segment a-b
  // needs no side vertex.
  bool are_adjacent(Index a, Index b) const;

  // The part of the loop from end a to end b that passes through `side` (both ends included, in the
  // direction a -> b); on an open line the one path from a to b, whatever `side` is. None when the
  // three are not distinct vertices of one loop.
  std::optional<std::vector<Index>> segment(Index a, Index b, Index side) const;

 private:
  std::vector<Index> loop_offsets_{0};
  std::vector<Index> loop_vertices_;
  std::vector<Index> loop_of_;
  std::vector<Index> position_;  // index of the vertex within its loop
  std::vector<unsigned char> is_closed_;
};

}  // namespace nome

#include "ops/subdivision/base_tiles.hpp"

#include <algorithm>

namespace nome {

std::vector<LevelCounts> level_counts(const Mesh& base, int k) {
  std::vector<LevelCounts> n(size_t(k) + 1);
  n[0] = {base.num_faces(), base.num_edges(), base.num_corners(), base.num_vertices()};
  for (size_t m = 1; m < n.size(); ++m) {
    const LevelCounts& p = n[m - 1];
    n[m] = {p.corners, 2 * p.edges + p.corners, 4 * p.corners, p.faces + p.edges + p.vertices};
  }
  return n;
}

namespace {

// CSR of the items whose owner is each base face.
void group_by_face(std::span<const Index> owner, Index faces, std::vector<Index>& offsets,
                   std::vector<Index>& items) {
  offsets.assign(size_t(faces) + 2, 0);
  for (Index f : owner)
    if (f != no_index) ++offsets[f + 2];
  for (size_t f = 2; f < offsets.size(); ++f) offsets[f] += offsets[f - 1];
  items.resize(offsets.back());
  for (Index i = 0; i < Index(owner.size()); ++i)
    if (owner[i] != no_index) items[offsets[owner[i] + 1]++] = i;
  offsets.pop_back();
}

}  // namespace

void BaseTiles::build(const Mesh& base) {
  face_corners.assign(base.face_offsets().begin(), base.face_offsets().end());
  lone_vertices.clear();
  owner.resize(base.num_edges());
  has_creases = false;
  for (Index e = 0; e < base.num_edges(); ++e) {
    const Edge& edge = base.edge(e);
    has_creases = has_creases || edge.is_sharp || edge.is_boundary();
    owner[e] = edge.faces[1] == no_index ? edge.faces[0] : std::max(edge.faces[0], edge.faces[1]);
  }
  group_by_face(owner, base.num_faces(), edge_offsets, edges);
  owner.assign(base.num_vertices(), no_index);
  for (Index v = 0; v < base.num_vertices(); ++v) {
    for (Index c : base.vertex_corners(v))
      owner[v] = owner[v] == no_index ? base.corner_face(c) : std::max(owner[v], base.corner_face(c));
    if (owner[v] == no_index) lone_vertices.push_back(v);
  }
  group_by_face(owner, base.num_faces(), vertex_offsets, vertices);
}

}  // namespace nome

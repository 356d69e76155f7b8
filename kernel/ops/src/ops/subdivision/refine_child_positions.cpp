#include <algorithm>

#include "ops/subdivision/base_tiles.hpp"
#include "ops/subdivision/tile_steps.hpp"
#include "support/parallel_for.hpp"

namespace nome {

// Three phases, each of which reads only what the ones before it wrote: G's faces, edges, vertices.
template <class Grandparent>
void refine_child_positions(const Grandparent& g, std::span<const Vec3> in, VertexRules rules,
                            std::span<Vec3> out, int threads) {
  const ChildPass<Grandparent> pass{g, in, out, rules.rule == SubdivisionRule::classic};
  parallel_for(g.num_faces(), threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) pass.face(f);
  });
  parallel_for(g.num_edges(), threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) pass.edge(e);
  });
  const Index vertex_points = pass.out_vp + pass.nf + pass.ne;
  parallel_for(g.num_vertices(), threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) pass.out[vertex_points + v] = pass.vertex_point(v, rules);
  });
}

// The classic rule reads only `in`, so its elements need no order: tile by tile (base_tiles.hpp, a tile
// being a few consecutive base faces), each tile's faces, edges and vertices while what they share is in
// the cache, the tiles split between threads.
// A thread's edges and vertices read the face points its earlier tiles wrote; each base edge and vertex
// belongs to the last tile around it, so on one thread they find all of them written.
void refine_child_positions_by_tile(const Refinement::Level& g, const BaseTiles& tiles,
                                    std::span<const LevelCounts> counts, std::span<const Vec3> in,
                                    VertexRules rules, std::span<Vec3> out, int threads,
                                    bool is_vector_allowed) {
  const LevelPass pass{g, in, out, true, tiles.has_creases};
  const TileSteps& steps = tile_steps(is_vector_allowed);
  const unsigned corner_shift = 2 * unsigned(counts.size() - 1);  // base corner -> its first G corner
  const Index base_faces = Index(tiles.face_corners.size() - 1);
  const Index per_tile = std::max<Index>(1, g.num_faces() / std::max<Index>(1, base_faces));  // G faces
  // About 2^10 faces of G a tile: what a tile reads and rewrites then fits in half of a 1 MB L2 cache, and
  // its index ranges are long enough for the hardware prefetchers (one base face a tile was 20 % slower).
  // Larger tiles leave two threads unevenly loaded, smaller ones cost more per tile than they save.
  const Index tile = std::max<Index>(1, (Index(1) << 10) / per_tile);
  const auto tiles_from = [&](Index begin, Index end) {
    ReadyCorners ready{tiles.face_corners[begin] << corner_shift, 0};
    const auto faces = [&](Index first, Index last) { steps.faces(pass, first, last); };
    const auto edges = [&](Index first, Index last) { steps.edges(pass, first, last, ready); };
    const auto vertices = [&](Index first, Index last) { steps.vertices(pass, first, last, rules, ready); };
    for (Index b = begin; b < end; b += tile) {
      const Index b_end = std::min(end, b + tile);
      ready.end = tiles.face_corners[b_end] << corner_shift;
      visit_tile(tiles, counts, b, b_end, faces, edges, vertices);
    }
  };
  // A G face is a few hundred instructions here: 2^12 of them a thread are worth a thread's start.
  parallel_for(base_faces, threads, tiles_from, std::max<Index>(1, (Index(1) << 12) / per_tile));
  const Index vertex_points = pass.out_vp + pass.nf + pass.ne;
  for (Index v : tiles.lone_vertices) {
    const Index at = tile_lone_vertex(counts, v);
    out[vertex_points + at] = pass.vertex_point(at, rules);
  }
}

template void refine_child_positions(const MeshLevelView&, std::span<const Vec3>, VertexRules,
                                     std::span<Vec3>, int);
template void refine_child_positions(const Refinement::Level&, std::span<const Vec3>, VertexRules,
                                     std::span<Vec3>, int);

}  // namespace nome

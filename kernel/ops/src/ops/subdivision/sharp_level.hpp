#pragma once

// Internal to subdivision: the semi-sharp features of one level, kept sparse (sorted lists, only what is
// there), and the pass that corrects the smooth position pass where they are. The smooth pass
// (refine_positions, refine_child_positions) already knows infinitely sharp and border edges; weights
// decay level by level, so these lists shrink to nothing unless a corner is infinitely sharp.

#include <span>
#include <utility>
#include <vector>

#include "nome/ops/crease_options.hpp"
#include "nome/ops/subdivide.hpp"
#include "ops/subdivision/refinement_level.hpp"

namespace nome {

struct SharpLevel {
  std::vector<std::pair<Index, float>> edges;     // semi-sharp edges and weights, by edge
  std::vector<std::pair<Index, float>> vertices;  // corner weights > 0, by vertex
  std::vector<Index> patch_edges;                 // edge points the smooth pass gets wrong, sorted
  std::vector<Index> patch_vertices;              // vertex points the same, sorted
  bool smooth_triangles = false;                  // the base level with CreaseOptions::smooth_triangles
  bool needs_topology = false;                    // false when only infinite corners are left
  Index num_faces = 0, num_edges = 0;             // of the level: where its child's points start

  bool empty() const { return patch_edges.empty() && patch_vertices.empty(); }
  float edge_weight(Index e) const;
  float vertex_weight(Index v) const;
};

// The base mesh's features: empty when it has no weights (and, with smooth triangles, no triangle).
SharpLevel base_sharp_level(const Mesh& base, const CreaseOptions& options);

// The features of the level after `p` (whose features are `s`): child edge weights by `method`, corner
// weights decayed. Reads p's topology only when s.needs_topology. `child_faces` and `child_edges` are the
// child level's counts.
template <class Parent>
SharpLevel child_sharp_level(const Parent& p, const SharpLevel& s, CreaseMethod method, Index child_faces,
                             Index child_edges);

// What a position pass needs besides the features.
struct SharpRules {
  CreaseMethod method = CreaseMethod::uniform;
  VertexRules vertex;
};

// Rewrites the child points of `s` in `out` (the level after `p`, already made by the smooth pass from
// `in`): edge points by OpenSubdiv's crease and blend masks, then vertex points by the rules of parent and
// child and the fractional blend between them.
template <class Parent>
void refine_sharp_positions(const Parent& p, const SharpLevel& s, const SharpRules& rules,
                            std::span<const Vec3> in, std::span<Vec3> out, int threads);

}  // namespace nome

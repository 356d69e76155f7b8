#include "ops/subdivision/tile_steps.hpp"

namespace nome {
// Named as well as anonymous: a unity build puts other files' anonymous namespaces beside this one.
namespace baseline_steps {
namespace {

void faces(const LevelPass& pass, Index first, Index last) {
  for (Index f = first; f < last; ++f) pass.face(f);
}

void edges(const LevelPass& pass, Index first, Index last, ReadyCorners ready) {
  for (Index e = first; e < last; ++e) pass.edge(e, ready);
}

void vertices(const LevelPass& pass, Index first, Index last, VertexRules rules, ReadyCorners ready) {
  const Index vertex_points = pass.out_vp + pass.nf + pass.ne;
  for (Index v = first; v < last; ++v) pass.out[vertex_points + v] = pass.vertex_point(v, rules, ready);
}

}  // namespace
}  // namespace baseline_steps

const TileSteps& tile_steps(bool is_vector_allowed) {
  static constexpr TileSteps baseline{baseline_steps::faces, baseline_steps::edges, baseline_steps::vertices};
  static const TileSteps* const best = avx2_tile_steps();
  return is_vector_allowed && best ? *best : baseline;
}

}  // namespace nome

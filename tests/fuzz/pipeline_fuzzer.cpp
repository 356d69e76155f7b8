#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fuzz/fuzz_target.hpp"
#include "nome/error.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene.hpp"
#include "support/funnel_cube_scene.hpp"

namespace {

// Settings from three bytes: the stage, merging, subdivision levels and rule, boundary mode, offset distance
// and levels after it, threads.
nome::PipelineSettings settings_from(const uint8_t* b) {
  nome::PipelineSettings s;
  s.stage = nome::builtin_stage_order()[b[0] % nome::builtin_stage_order().size()];
  s.should_merge = (b[0] >> 3) & 1;
  s.subdivision_levels = (b[0] >> 4) % 3;
  s.rule = (b[0] >> 6) & 1 ? nome::SubdivisionRule::report : nome::SubdivisionRule::classic;
  s.boundary = static_cast<nome::BoundaryMode>(b[1] % 3);
  s.offset_distance = ((b[1] >> 2) % 8) * 0.01;
  s.subdivision_after = s.offset_distance > 0 ? (b[1] >> 5) % 2 : 0;
  s.threads = 1 + (b[2] & 1);
  return s;
}

bool is_same_mesh(const nome::Mesh& a, const nome::Mesh& b) {
  if (a.num_faces() != b.num_faces() || a.num_vertices() != b.num_vertices()) return false;
  for (nome::Index v = 0; v < a.num_vertices(); ++v)
    if (a.position(v) != b.position(v)) return false;
  return true;
}

}  // namespace

// The caching pipeline under random settings and slider moves: after every move (and change of levels)
// the pipeline that was fed only what changed (moved vertices, or new polygons) gives the same result as a
// new pipeline run on the scene from scratch. A slider value the scene refuses is a located refusal.
NOME_FUZZ_TARGET(pipeline) {
  if (size < 3) return 0;
  nome::PipelineSettings settings = settings_from(data);
  nome::scene::Scene scene = nome::scene::Scene::from_text(nome::test::funnel_cube_scene, "fuzz.nome");
  nome::Pipeline live;
  live.set_input(nome::PipelineInput{scene.combined_soup(), {}, nome::Joining::manifold});
  live.run(settings);
  for (size_t i = 3; i + 2 < size; i += 3) {
    // Each step: a slider and its value, and the subdivision levels before and after the offset.
    settings.subdivision_levels = data[i + 2] % 3;
    settings.subdivision_after = settings.offset_distance > 0 ? (data[i + 2] >> 2) % 2 : 0;
    const nome::scene::ParameterId id(data[i] % nome::Index(scene.parameters().size()));
    const nome::scene::Parameter& p = scene.parameters()[id];
    // Odd bytes: anywhere in the range; even ones: on the slider's steps (whole counts among them).
    const double anywhere = p.min + (p.max - p.min) * data[i + 1] / 255.0;
    const double on_step = p.step > 0 ? p.min + p.step * std::round((anywhere - p.min) / p.step) : anywhere;
    try {
      scene.set_parameter(id, std::clamp(data[i + 1] % 2 ? anywhere : on_step, p.min, p.max));
    } catch (const nome::Error& e) {
      nome::fuzz::require_located_refusal(e, "fuzz.nome");
      continue;
    }
    if (scene.last_change_moved_vertices_only())
      live.move_input_vertices(scene.combined_positions());
    else
      live.set_input(nome::PipelineInput{scene.combined_soup(), {}, nome::Joining::manifold});
    const nome::Mesh& incremental = live.run(settings);
    nome::Pipeline fresh;
    fresh.set_input(nome::PipelineInput{scene.combined_soup(), {}, nome::Joining::manifold});
    if (!is_same_mesh(incremental, fresh.run(settings))) std::abort();
  }
  return 0;
}

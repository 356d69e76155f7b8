// Live editing figures (issue 6): a slider change to new display buffers, as the viewer does it: the
// scene re-evaluates what reads the slider, the editing document takes the new geometry, and the stage
// pipeline runs the stages and builds the GPU-ready arrays (all but the GL upload). The picking BVH waits
// for the first pick after a change: timed apart, with that pick.
// Target (issue 6): median under 16 ms for funnel_cube_consolidated, merged, subdivision 3, offset.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "nome/query/triangle_bvh.hpp"
#include "viewer/session.hpp"
#include "viewer/stage_pipeline.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main() {
  using namespace nome;
  using namespace nome::viewer;
  Session session = Session::open(NOME_SOURCE_DIR "/assets/funnel_cube_consolidated.nome");
  StagePipeline pipeline;
  PipelineSettings settings = initial_settings();
  settings.stage = Stage::offset;
  settings.subdivision_levels = 3;
  settings.offset_distance = 0.05;
  auto run = [&] { return pipeline.run(session.pipeline_input(), settings, std::stop_token{}); };
  const auto first = run();
  std::printf(
      "slider: funnel_cube_consolidated, merged, subdivision 3, %s stage (offset 0.05): %u faces on screen\n",
      to_string(settings.stage), first->mesh->num_faces());
  struct Slider {
    const char* name;
    double a, b;
    const char* what;
  };
  const Slider sliders[] = {{"fp_h", 0.3, 0.4, "moves vertices"}, {"fp_n", 8, 7, "changes the topology"}};
  for (const Slider& slider : sliders) {
    std::vector<double> total, scene, stages, first_pick;
    for (int i = 0; i < 21; ++i) {
      const auto start = Clock::now();
      session.set_parameter(slider.name, i % 2 ? slider.a : slider.b);
      scene.push_back(ms_since(start));
      const auto stage_start = Clock::now();
      const auto result = run();
      stages.push_back(ms_since(stage_start));
      total.push_back(ms_since(start));
      if (!result || result->mesh->num_faces() == 0) return 1;
      const auto pick_start = Clock::now();
      const nome::TriangleBvh bvh(*result->mesh);
      // A ray down onto a vertex: it hits the surface there at least.
      const nome::Ray ray{result->mesh->position(0) + nome::Vec3(0.0, 0.0, 10.0), nome::Vec3(0.0, 0.0, -1.0)};
      if (!bvh.cast_nearest(ray)) return 1;
      first_pick.push_back(ms_since(pick_start));
    }
    std::printf(
        "  %-5s (%s): median %7.2f ms  (scene %5.2f ms, stages + buffers %6.2f ms; target < 16 ms); "
        "first pick after it %5.2f ms\n",
        slider.name, slider.what, median(total), median(scene), median(stages), median(first_pick));
  }
  return 0;
}

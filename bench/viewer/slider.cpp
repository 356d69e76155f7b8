// Live editing figures (issue 6): a slider change to new display buffers, as the viewer does it: the
// scene re-evaluates what reads the slider, the editing document takes the new geometry, and the stage
// pipeline runs the stages and builds the GPU-ready arrays and the picking BVH (all but the GL upload).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

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
  using namespace nome::viewer;
  Session session = Session::open(NOME_SOURCE_DIR "/assets/funnel_cube_consolidated.nome");
  StagePipeline pipeline;
  StageSettings settings;
  settings.stage = Stage::merged;
  auto run = [&] { return pipeline.run(session.scene_soup(), settings, std::stop_token{}); };
  const auto first = run();
  std::printf("slider: funnel_cube_consolidated, %s stage: %u faces on screen\n", to_string(settings.stage),
              first->mesh->num_faces());
  struct Slider {
    const char* name;
    double a, b;
    const char* what;
  };
  const Slider sliders[] = {{"fp_h", 0.3, 0.4, "moves vertices"}, {"fp_n", 8, 7, "changes the topology"}};
  for (const Slider& slider : sliders) {
    std::vector<double> total, scene, stages;
    for (int i = 0; i < 21; ++i) {
      const auto start = Clock::now();
      session.set_parameter(slider.name, i % 2 ? slider.a : slider.b);
      scene.push_back(ms_since(start));
      const auto stage_start = Clock::now();
      const auto result = run();
      stages.push_back(ms_since(stage_start));
      total.push_back(ms_since(start));
      if (!result || result->mesh->num_faces() == 0) return 1;
    }
    std::printf(
        "  %-5s (%s): median %7.2f ms  (scene %5.2f ms, stages + buffers + BVH %6.2f ms; target < 16 ms)\n",
        slider.name, slider.what, median(total), median(scene), median(stages));
  }
  return 0;
}

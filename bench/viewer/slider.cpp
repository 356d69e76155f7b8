// Live editing figures: a slider change to new display buffers, as the viewer does it: the scene
// re-evaluates what reads the slider, the stage pipeline runs the stages and builds the GPU-ready arrays,
// the renderer updates its buffers. The picking BVH waits for the first pick after a change: timed apart,
// with that pick. Each figure is printed beside its target: funnel_cube_consolidated merged, subdivision
// 3, offset, a slider that moves vertices within 1 ms and one that changes the topology within 16 ms; on
// a 64x32 torus merged, subdivided and offset, at 1,048,576 faces the kernel's positions, the display
// arrays and the vertex buffers within 16 ms on two threads (without the draw); at 262,144 faces a whole
// frame, draw included, within 33 ms on llvmpipe; a slider that changes the topology never stalls a
// frame; the viewer's first offset solid within 1.5x of the warm one.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string_view>
#include <vector>

#include "nome/freed_memory.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "render/offscreen_context.hpp"
#include "render/scene_renderer.hpp"
#include "slider_frames.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

namespace {

using nome::bench::median;
using nome::bench::ms_since;
using Clock = std::chrono::steady_clock;

void funnel_figures() {
  using namespace nome;
  using namespace nome::viewer;
  Session session = Session::open(NOME_SOURCE_DIR "/assets/funnel_cube_consolidated.nome");
  StagePipeline pipeline;
  PipelineSettings settings = initial_settings();
  settings.stage = Stage::offset;
  settings.subdivision_levels = 3;
  settings.offset_distance = 0.05;
  auto run = [&] { return pipeline.run(session.scene_input(), settings, nome::stop_token{}); };
  const auto first = run();
  std::printf(
      "slider: funnel_cube_consolidated, merged, subdivision 3, %s stage (offset 0.05): %u faces on screen\n",
      to_string(settings.stage), first->mesh->num_faces());
  struct Slider {
    const char* name;
    double a, b;
    const char* what;
    double target_ms;
  };
  const Slider sliders[] = {{"fp_h", 0.3, 0.4, "moves vertices", 1.0},
                            {"fp_n", 8, 7, "changes the topology", 16.0}};
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
      if (!result || result->mesh->num_faces() == 0) std::exit(1);
      const auto pick_start = Clock::now();
      const nome::TriangleBvh bvh(*result->mesh);
      // A ray down onto a vertex: it hits the surface there at least.
      const nome::Ray ray{result->mesh->position(0) + nome::Vec3(0.0, 0.0, 10.0), nome::Vec3(0.0, 0.0, -1.0)};
      if (!bvh.cast_nearest(ray)) std::exit(1);
      first_pick.push_back(ms_since(pick_start));
    }
    std::printf(
        "  %-5s (%s): median %7.2f ms (target <= %.0f ms; scene %5.2f ms, stages + display arrays %6.2f "
        "ms); first pick after it %5.2f ms\n",
        slider.name, slider.what, median(total), slider.target_ms, median(scene), median(stages),
        median(first_pick));
  }
}

}  // namespace

// `--million`: only the slider that moves vertices at a million faces; `--frame`: only the frames at
// 262,144 faces (each for a profiler); `--first-solid`: only the viewer's first solid; `--funnel`: only the
// funnel cube's sliders.
int main(int argc, char** argv) {
  nome::keep_freed_memory();  // as the nome program does
  const std::string_view only = argc > 1 ? argv[1] : "";
  if (only == "--first-solid-child") return nome::bench::print_first_solid();
  if (only.empty() || only == "--funnel") funnel_figures();
  if (only == "--funnel") return 0;
  if (only.empty() || only == "--first-solid") nome::bench::first_solid_figures();
  if (only == "--first-solid") return 0;
  const nome::render::OffscreenContext context(nome::render::Backend::egl);
  std::printf("live at a million faces, %s (%s):\n", context.platform().c_str(),
              context.description().c_str());
  if (only != "--frame") nome::bench::million_figures();
  if (only != "--million") nome::bench::frame_figures();
  return 0;
}

// The viewer's first solid (as the viewer meets it): the offset of the level-5 torus
// (4,194,304 faces) with everything a frame needs of it (StagePipeline: the kernel's stages, the display
// arrays, borders, report), the first time in a new process and warm.
#include <cstdio>
#include <string>

#include "slider_frames.hpp"
#include "support/new_process.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

namespace nome::bench {
namespace {

struct FirstSolid {
  double first_ms = 0, warm_ms = 0;
  Index faces = 0;
};

// Shows the subdivided torus, then its offset, as a user turning the offset on does; then, three times,
// the subdivision again and the offset again (its solid made again, into kept memory).
FirstSolid time_first_solid() {
  using namespace nome::viewer;
  Session session = Session::open(NOME_SOURCE_DIR "/bench/viewer/slider_torus.nome");
  PipelineSettings subdivided = initial_settings();
  subdivided.stage = Stage::subdivided;
  subdivided.subdivision_levels = 5;
  PipelineSettings offset = subdivided;
  offset.stage = Stage::offset;
  offset.offset_distance = 0.01;
  StagePipeline stages;
  auto run = [&](const PipelineSettings& s) {
    auto result = stages.run(session.scene_input(), s, nome::stop_token{});
    if (!result) std::exit(1);
    return result->mesh->num_faces();
  };
  run(subdivided);
  FirstSolid times;
  auto start = std::chrono::steady_clock::now();
  times.faces = run(offset);
  times.first_ms = ms_since(start);
  times.warm_ms = 1e30;
  for (int i = 0; i < 3; ++i) {
    run(subdivided);
    start = std::chrono::steady_clock::now();
    run(offset);
    times.warm_ms = std::min(times.warm_ms, ms_since(start));
  }
  return times;
}

}  // namespace

int print_first_solid() {
  const FirstSolid times = time_first_solid();
  std::printf("%f %f %u\n", times.first_ms, times.warm_ms, times.faces);
  return 0;
}

// In a new process (output_of_new_process), as nome_bench_subdivide's first offset: a user's new viewer
// finds its memory so.
void first_solid_figures() {
  FirstSolid times;
  const std::string output = output_of_new_process("--first-solid-child");
  if (std::sscanf(output.c_str(), "%lf %lf %u", &times.first_ms, &times.warm_ms, &times.faces) != 3)
    times = {};
  std::printf(
      "  the viewer's first solid (goal 2 as the viewer meets it): the offset of the level-5 torus, %u "
      "faces, "
      "with its display arrays, borders and report: %.0f ms the first time in a process, %.0f ms warm "
      "(%.2fx; target 1.5x) (wall time)\n",
      times.faces, times.first_ms, times.warm_ms, times.first_ms / times.warm_ms);
}

}  // namespace nome::bench

// Sculpting by hand, one drag step as the viewer makes it each frame: the drag says what to change (the
// sliders solved for, or the text's numbers rewritten), the session takes it (sliders moved, or the text
// read again, its vertices alone moving while the faces stay), and the stage pipeline runs the stages and
// builds the display arrays. Targets: under 16 ms a step, solving included, on the consolidated funnel cube
// (sliders) and on a subdivided result of about 100,000 faces (the figure-8 Klein bottle at level 5, 98,304
// faces; a point of the hand-made Moebius band, its text rewritten, at level 7, 131,072 faces); and the
// funnel cube subdivided and offset at 161,280 faces.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "nome/edit/scene_drag.hpp"
#include "nome/freed_memory.hpp"
#include "slider_frames.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

namespace {

using nome::bench::median;
using nome::bench::ms_since;
using Clock = std::chrono::steady_clock;

void drag_figures(const char* file, const char* vertex, nome::Stage stage, int levels, const char* what) {
  using namespace nome;
  using namespace nome::viewer;
  Session session = Session::open(std::string(NOME_SOURCE_DIR "/assets/") + file);
  StagePipeline pipeline;
  PipelineSettings settings = initial_settings();
  settings.stage = stage;
  settings.subdivision_levels = levels;
  settings.offset_distance = 0.05;
  auto run = [&] { return pipeline.run(session.scene_input(), settings, nome::stop_token{}); };
  const auto first = run();
  const std::string name = session.scene()->resolve_vertex_name(vertex);
  const auto begin_start = Clock::now();
  SceneDrag drag(*session.scene(), session.text(), {{name}, {}});
  const double begin_ms = ms_since(begin_start);
  std::vector<double> total, solve, apply, stages;
  for (int i = 1; i <= 41; ++i) {
    // A drag that wanders: a small circle about the press, as a hand moves the mouse.
    const double a = 0.3 * i;
    const Vec3 offset(0.15 * std::cos(a), 0.15 * std::sin(a), 0.05 * std::sin(2 * a));
    const auto start = Clock::now();
    const DragStep step = drag.move(offset);
    solve.push_back(ms_since(start));
    const auto apply_start = Clock::now();
    session.apply_drag_step(replaced_text(drag.text(), step.replacements), step.sliders);
    apply.push_back(ms_since(apply_start));
    const auto stage_start = Clock::now();
    const auto result = run();
    stages.push_back(ms_since(stage_start));
    total.push_back(ms_since(start));
    if (!result || result->mesh->num_faces() != first->mesh->num_faces()) std::exit(1);
  }
  std::printf(
      "drag: %s, %s %s (%u faces on screen), %s (%s): one step median %6.2f ms (target < 16 ms; solve %5.2f "
      "ms, "
      "scene %5.2f ms, stages + display arrays %6.2f ms); the press %5.2f ms\n",
      file, to_string(stage), levels > 0 ? ("level " + std::to_string(levels)).c_str() : "",
      first->mesh->num_faces(), vertex, what, median(total), median(solve), median(apply), median(stages),
      begin_ms);
}

}  // namespace

int main() {
  nome::keep_freed_memory();  // as the nome program does
  drag_figures("funnel_cube_consolidated.nome", "fun1_bc5", nome::Stage::merged, 0, "its sliders solved for");
  drag_figures("funnel_cube_consolidated.nome", "fun1_hc3", nome::Stage::subdivided, 3,
               "its sliders solved for");
  drag_figures("klein_bottle_figure8.nome", "p0_1", nome::Stage::subdivided, 5, "its slider solved for");
  drag_figures("funnel_cube_consolidated.nome", "fun1_hc3", nome::Stage::offset, 5, "its sliders solved for");
  drag_figures("hand_made_mobius_band.nome", "m_o2", nome::Stage::subdivided, 7,
               "its point's numbers rewritten");
  return 0;
}

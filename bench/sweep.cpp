// Sweeps: a cross-section of 32 points along 10,000 path samples, evaluated into the mesh the
// pipeline uses, and re-evaluated when a slider moves a point of its path. One thread, CPU time, best of 5.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <numbers>
#include <string>

#include "nome/freed_memory.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene.hpp"
#include "nome/scene/sweep.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

double now_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double best_ms(int runs, const std::function<void()>& work) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const double start = now_ms();
    work();
    best = std::min(best, now_ms() - start);
  }
  return best;
}

// A (3, 2) torus knot of 10,000 samples, closed, in the scene language: a B-spline through 12 points, one
// of them moved by the slider.
std::string knot_scene() {
  std::string text = "bank b set lift 0 -1 1 0.01 endbank\n";
  std::string names;
  for (int i = 0; i < 12; ++i) {
    const double t = 2 * std::numbers::pi * i / 12;
    const double r = 4 + std::cos(3 * t);
    const std::string z = i == 0 ? "{expr $b_lift}" : std::to_string(std::sin(3 * t));
    text += "point k" + std::to_string(i) + " (" + std::to_string(r * std::cos(2 * t)) + " " +
            std::to_string(r * std::sin(2 * t)) + " " + z + ") endpoint\n";
    names += "k" + std::to_string(i) + " ";
  }
  text += "bspline path order 4 (" + names + "k0 k1 k2) segs 10000 endbspline\n";
  text += "circle section (32 0.3) endcircle\n";
  text += "sweep s crosssection section endcrosssection path path mintorsion twist (90) endpath endsweep\n";
  text += "instance i s endinstance\n";
  return text;
}

// The core alone (frames, placement and faces), and its soup into the pipeline without the scene.
void core_figures() {
  std::vector<PathSample> path;
  for (int i = 0; i < 10000; ++i) {
    const double t = 2 * std::numbers::pi * i / 10000;
    const double r = 4 + std::cos(3 * t);
    path.push_back({Vec3(r * std::cos(2 * t), r * std::sin(2 * t), std::sin(3 * t))});
  }
  CrossSection circle{{}, true};
  for (int j = 0; j < 32; ++j)
    circle.points.emplace_back(0.3 * std::cos(2 * std::numbers::pi * j / 32),
                               0.3 * std::sin(2 * std::numbers::pi * j / 32));
  SweepOptions o;
  o.frames = FrameKind::minimal_torsion;
  o.is_path_closed = true;
  o.twist = 90;
  SweepResult result;
  std::printf("  sweep() core (frames, vertices, faces, names)  %8.2f\n", best_ms(5, [&] {
                result = sweep(path, {&circle, 1}, o);
              }));
  Buffer<Vec3> moved;
  std::printf("  sweep_positions() (what a slider move changes)  %8.2f\n", best_ms(5, [&] {
                moved = sweep_positions(path, {&circle, 1}, o).positions;
              }));
  Mesh mesh;
  std::printf("  build_mesh of its soup                         %8.2f\n",
              best_ms(5, [&] { mesh = build_mesh(result.piece.soup); }));

  Pipeline direct;
  PipelineSettings scene_stage;
  scene_stage.stage = Stage::scene;
  direct.set_input(PipelineInput{result.piece.soup, {}, {}});
  direct.run(scene_stage);
  std::printf("  slider move, positions path: sweep_positions() into the pipeline's mesh %8.2f\n",
              best_ms(5, [&] {
                direct.move_input_vertices(sweep_positions(path, {&circle, 1}, o).positions);
                direct.run(scene_stage);
              }));
}

// Through the scene and the pipeline's scene stage, as the viewer and `nome info` do.
void scene_figures() {
  const std::string text = knot_scene();
  PipelineSettings settings;
  settings.stage = Stage::scene;
  Pipeline pipeline;
  std::optional<Scene> scene;
  std::printf("  scene: parse and evaluate the sweep            %8.2f\n",
              best_ms(5, [&] { scene.emplace(Scene::from_text(text, "bench.nome")); }));
  std::printf("  scene soup into the pipeline (new topology)    %8.2f\n", best_ms(5, [&] {
                pipeline = Pipeline();
                pipeline.set_input(PipelineInput{scene->combined_soup(), {}, {}});
                pipeline.run(settings);
              }));
  std::printf("  first evaluation: text to the pipeline's mesh   %8.2f   (target <= 20, from 16: kept)\n",
              best_ms(5, [&] {
                scene.emplace(Scene::from_text(text, "bench.nome"));
                pipeline = Pipeline();
                pipeline.set_input(PipelineInput{scene->combined_soup(), {}, {}});
                pipeline.run(settings);
              }));
  const scene::ParameterId lift = *scene->find_parameter("b_lift");
  double value = 0;
  std::printf("  slider move: re-evaluate the sweep             %8.2f\n",
              best_ms(5, [&] { scene->set_parameter(lift, value = value > 0.5 ? 0 : value + 0.1); }));
  std::printf("  slider move: re-evaluate, soup into the pipeline %6.2f\n", best_ms(5, [&] {
                scene->set_parameter(lift, value = value > 0.5 ? 0 : value + 0.1);
                pipeline.set_input(PipelineInput{scene->combined_soup(), {}, {}});
                pipeline.run(settings);
              }));
  // As SceneDocument does when no instance's topology_version changed.
  std::printf("  slider move: re-evaluate, positions into the pipeline %8.2f   (target <= 20)\n",
              best_ms(5, [&] {
                scene->set_parameter(lift, value = value > 0.5 ? 0 : value + 0.1);
                pipeline.move_input_vertices(scene->combined_positions());
                pipeline.run(settings);
              }));
  std::printf("  (sweep placements moved without a whole evaluation: %zu)\n", scene->vertex_moves());
  std::printf("  (pipeline scene stage work on the move: %s)\n",
              pipeline.work(Stage::scene) == StageWork::positions ? "positions only" : "rebuilt");
}

}  // namespace

int main() {
  nome::keep_freed_memory();  // as the nome program does
  std::printf("sweep: 10,000 path samples x 32 cross-section points (320,000 quads), best of 5, CPU ms\n");
  core_figures();
  scene_figures();
  return 0;
}

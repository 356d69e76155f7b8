#include "slider_frames.hpp"

#include <sys/resource.h>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <thread>

#include "nome/ops/pipeline.hpp"
#include "render/framebuffer.hpp"
#include "render/gl.hpp"
#include "render/scene_renderer.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"
#include "viewer/session/stage_view.hpp"

namespace nome::bench {
namespace {

using Clock = std::chrono::steady_clock;
using namespace nome::viewer;

const char* const scene_path = NOME_SOURCE_DIR "/bench/viewer/slider_torus.nome";

PipelineSettings torus_settings(int levels) {
  PipelineSettings s = initial_settings();
  s.stage = Stage::offset;
  s.subdivision_levels = levels;
  s.offset_distance = 0.02;
  return s;
}

// The machine's load and llvmpipe's rasteriser threads (LP_NUM_THREADS, else one per core), which
// together decide its speed.
std::string load() {
  double loads[3] = {};
  const char* threads = std::getenv("LP_NUM_THREADS");
  char text[128];
  std::snprintf(
      text, sizeof text, "load %s, LP_NUM_THREADS %s",
      getloadavg(loads, 3) < 1 ? "unknown" : std::to_string(loads[0]).substr(0, 4).c_str(),
      threads ? threads : ("unset: " + std::to_string(std::thread::hardware_concurrency())).c_str());
  return text;
}

// Applies a stage result to the renderer as the window does (in place when its topology is on display).
void show(render::SceneRenderer& renderer, const StageResult& result) {
  renderer.set_mesh(result.display);
}

// A slider that changes the topology: the frames go on while the job runs.
void topology_figures(Session& session, const StageView& view, const std::function<void(double)>& frame,
                      Index faces, double steady_ms) {
  double longest = 0.0, swap = 0.0, until_shown = 0.0;
  int frames = 0;
  for (int i = 0; i < 4; ++i) {
    session.set_parameter("t_segs", i % 2 ? 64 : 60);
    const auto start = Clock::now();
    do {
      const Mesh* before = view.shown_mesh();
      const auto frame_start = Clock::now();
      frame(1.0);
      const double ms = ms_since(frame_start);
      // The frame that takes the new solid uploads its topology; the others only draw.
      if (view.shown_mesh() == before)
        longest = std::max(longest, ms);
      else
        swap = std::max(swap, ms);
      ++frames;
    } while (view.is_busy());
    until_shown = std::max(until_shown, ms_since(start));
  }
  std::printf(
      "  slider t_segs (changes the topology) at about %u faces: the last solid stays up, %d frames drawn, "
      "longest frame while the job runs %.1f ms, the frame that swaps the new solid in %.1f ms, against "
      "%.1f ms for a frame without a change (target: no frame stalls on the job); new solid shown after "
      "at most %.0f ms [%s]\n",
      faces, frames, longest, swap, steady_ms, until_shown, load().c_str());
}

// The shown mesh's triangles over its own vertices (no extra GL vertices).
std::vector<std::uint32_t> own_triangles(const StageResult& shown) {
  const render::DisplayTopology& topology = *shown.display.topology;
  std::vector<std::uint32_t> triangles(topology.triangles.begin(), topology.triangles.end());
  for (std::uint32_t& u : triangles)
    if (u >= topology.num_vertices)
      u = topology.extra_vertices[u - topology.num_vertices] & ~render::corner_sign_bit;
  return triangles;
}

// The shown mesh's GL vertices, and its triangles drawn with a trivial shader: llvmpipe's floor.
void floor_figures(const StageResult& shown, const glm::mat4& transform, glm::ivec2 size) {
  const render::DisplayTopology& topology = *shown.display.topology;
  std::printf("  at %u faces: %u GL vertices (%.2f per mesh vertex), %zu triangles\n", topology.num_faces,
              topology.num_gl_vertices(), double(topology.num_gl_vertices()) / topology.num_vertices,
              topology.triangles.size() / 3);
  const std::vector<std::uint32_t> triangles = own_triangles(shown);
  const auto& positions = shown.display.positions->vertices;
  const TrivialDraw floor = trivial_draw(positions, triangles, transform, size);
  const TrivialDraw tiny = trivial_draw(positions, triangles, transform, {16, 16});
  std::printf(
      "  the same %zu triangles with a trivial shader (llvmpipe's floor): %.1f ms (%.1f ms CPU, all "
      "threads); "
      "into 16x16 pixels %.1f ms (%.1f ms CPU) [%s]\n",
      triangles.size() / 3, floor.wall_ms, floor.cpu_ms, tiny.wall_ms, tiny.cpu_ms, load().c_str());
}

// The renderer's draw alone into `viewport` of the bound framebuffer, median wall and CPU milliseconds.
TrivialDraw time_draws(render::SceneRenderer& renderer, const render::Camera& camera, glm::ivec2 size,
                       glm::ivec2 viewport) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < 5; ++i) {
    const auto start = Clock::now();
    const double cpu_start = cpu_ms();
    renderer.draw(camera, size, {{0, 0}, viewport}, render::DisplaySettings{});
    glFinish();
    wall.push_back(ms_since(start));
    cpu.push_back(cpu_ms() - cpu_start);
  }
  return {median(wall), median(cpu)};
}

// The same draw and its floor into a framebuffer of one sample per pixel: what 4x multisampling costs
// llvmpipe (the viewer's window asks for four).
void single_sample_figures(const StageResult& shown, const render::Camera& camera,
                           render::SceneRenderer& renderer, glm::ivec2 size) {
  const render::Framebuffer framebuffer(size.x, size.y, 0);
  framebuffer.bind();
  const TrivialDraw draw = time_draws(renderer, camera, size, size);
  const glm::mat4 transform = camera.projection_matrix(double(size.x) / size.y) * camera.view_matrix();
  const TrivialDraw floor =
      trivial_draw(shown.display.positions->vertices, own_triangles(shown), transform, size);
  std::printf(
      "  without multisampling (%dx%d, 1 sample): the draw %.1f ms (%.1f ms CPU), the trivial floor %.1f ms "
      "(%.1f ms CPU) [%s]\n",
      size.x, size.y, draw.wall_ms, draw.cpu_ms, floor.wall_ms, floor.cpu_ms, load().c_str());
}

// Five frames with nothing new to show: median wall and CPU milliseconds.
template <class Frame>
TrivialDraw time_frames(const Frame& frame) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < 5; ++i) {
    const auto start = Clock::now();
    const double cpu_start = cpu_ms();
    frame(0.0);
    wall.push_back(ms_since(start));
    cpu.push_back(cpu_ms() - cpu_start);
  }
  return {median(wall), median(cpu)};
}

struct SliderFrames {
  double frame_ms = 0, latency_ms = 0;  // medians
};

// Eleven slider moves, each from the change to the frame that shows its result (the job runs beside the
// frames): the frames' time and the changes' latency.
template <class Frame>
SliderFrames slider_frames(Session& session, const StageView& view, const Frame& frame) {
  std::vector<double> frame_ms, latency_ms;
  for (int i = 0; i < 11; ++i) {
    session.set_parameter("t_r", i % 2 ? 0.35 : 0.36);
    const auto start = Clock::now();
    do {
      const auto frame_start = Clock::now();
      frame(0.0);
      frame_ms.push_back(ms_since(frame_start));
    } while (view.is_busy());
    latency_ms.push_back(ms_since(start));
  }
  return {median(frame_ms), median(latency_ms)};
}

}  // namespace

void million_figures() {
  Session session = Session::open(scene_path);
  PipelineSettings settings = torus_settings(4);
  settings.threads = 2;  // the target's
  Pipeline kernel;
  StagePipeline stages, compared;
  const auto renderer = render::make_gl_scene_renderer();
  kernel.set_input(session.pipeline_input());
  const Index faces = kernel.run(settings).num_faces();
  show(*renderer, *stages.run(session.scene_input(), settings, {}));
  compared.run(session.pipeline_input(), settings, {});
  std::vector<double> kernel_ms, stage_ms, buffer_ms, kernel_cpu, stage_cpu, compared_ms;
  for (int i = 0; i < 11; ++i) {
    session.set_parameter("t_r", i % 2 ? 0.35 : 0.36);
    auto start = Clock::now();
    double cpu = cpu_ms();
    kernel.move_input_vertices(session.positions());
    kernel.run(settings);
    kernel_ms.push_back(ms_since(start));
    kernel_cpu.push_back(cpu_ms() - cpu);
    start = Clock::now();
    cpu = cpu_ms();
    const auto result = stages.run(session.scene_input(), settings, {});
    stage_ms.push_back(ms_since(start));
    stage_cpu.push_back(cpu_ms() - cpu);
    if (!result) std::exit(1);
    start = Clock::now();
    show(*renderer, *result);
    glFinish();
    buffer_ms.push_back(ms_since(start));
    // The way a tick went before the scene told moved vertices from new faces: its whole input copied
    // and compared with the last one.
    start = Clock::now();
    if (!compared.run(session.pipeline_input(), settings, {})) std::exit(1);
    compared_ms.push_back(ms_since(start));
  }
  const double k = median(kernel_ms), s = median(stage_ms), b = median(buffer_ms);
  const double kc = median(kernel_cpu), sc = median(stage_cpu);
  std::printf(
      "  slider t_r (moves vertices) at %u faces, subdivision 4 + offset, %d threads: kernel %.1f ms + "
      "display arrays %.1f ms + buffer update %.1f ms = %.1f ms (target <= 16 ms, from 35 ms) [%s]; "
      "CPU time, all threads: kernel %.1f ms, display arrays %.1f ms; kernel and display "
      "arrays with the input compared whole, as before the change signal: %.1f ms\n",
      faces, settings.threads, k, s - k, b, s + b, load().c_str(), kc, sc - kc, median(compared_ms));
}

void frame_figures() {
  Session session = Session::open(scene_path);
  const PipelineSettings settings = torus_settings(3);
  const auto renderer = render::make_gl_scene_renderer();
  const glm::ivec2 size{1280, 800};
  const render::Framebuffer framebuffer(size.x, size.y, 4);
  framebuffer.bind();
  StageView view;
  view.settings() = settings;
  render::Camera camera;
  camera.set_view(30, 25);
  const render::DisplaySettings display;
  auto frame = [&](double now) {
    // The window's frame: take a finished result if any, show it, draw.
    view.request(session);
    if (auto result = view.take_for_frame()) {
      show(*renderer, *result);
      view.show(std::move(*result), now);
    }
    renderer->draw(camera, size, {{0, 0}, size}, display);
    glFinish();
  };
  while (!view.shown()) frame(0.0);
  camera.fit(view.shown_mesh()->positions(), double(size.x) / size.y);
  const Index faces = view.shown_mesh()->num_faces();
  floor_figures(*view.shown(), camera.projection_matrix(double(size.x) / size.y) * camera.view_matrix(),
                size);
  const TrivialDraw draw = time_frames(frame);
  // The same draw into a viewport of 16x16 pixels: what the vertices cost.
  const double vertex_cpu = time_draws(*renderer, camera, size, {16, 16}).cpu_ms;
  const SliderFrames slider = slider_frames(session, view, frame);
  std::printf(
      "  slider t_r (moves vertices) at %u faces, 1280x800 4x MSAA: whole frame, draw included, median %.1f "
      "ms (target < 33 ms), from the change to its picture %.1f ms; the draw alone %.1f ms (%.1f ms CPU, "
      "all threads; %.1f ms CPU into 16x16 pixels) [%s]\n",
      faces, slider.frame_ms, slider.latency_ms, draw.wall_ms, draw.cpu_ms, vertex_cpu, load().c_str());
  single_sample_figures(*view.shown(), camera, *renderer, size);
  framebuffer.bind();
  topology_figures(session, view, frame, faces, draw.wall_ms);
}

double cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3 +
         (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-3;
}

}  // namespace nome::bench

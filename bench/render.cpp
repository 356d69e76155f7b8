// Headless rendering figures: what one `nome render` costs, piece by piece, and what a viewer
// frame costs on llvmpipe, at 1024x768 with and without 4x multisampling (`nome render` uses 4x).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "render/camera.hpp"
#include "render/framebuffer.hpp"
#include "render/mesh_buffers.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "torus.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

using nome::bench::torus;

void measure(const nome::render::Renderer& renderer, const nome::Mesh& mesh, bool wire, int samples) {
  using namespace nome::render;
  const int width = 1024, height = 768;
  auto start = Clock::now();
  const MeshDisplayData data = build_display_data(mesh);
  const double build_ms = ms_since(start);
  start = Clock::now();
  const MeshBuffers buffers(data);
  glFinish();
  const double upload_ms = ms_since(start);
  const Framebuffer framebuffer(width, height, samples);
  framebuffer.bind();
  Camera camera;
  camera.set_view(30, 25);
  camera.fit(mesh.positions(), double(width) / height);
  DisplaySettings settings;
  settings.draws_wireframe = wire;
  std::vector<double> frames;
  for (int i = 0; i < 12; ++i) {
    camera.set_view(30 + 3 * i, 25);
    const auto frame = Renderer::Frame::of(camera, {0, 0}, {width, height});
    start = Clock::now();
    renderer.begin(frame, settings.background);
    renderer.draw_mesh(buffers, frame, settings);
    glFinish();
    frames.push_back(ms_since(start));
  }
  start = Clock::now();
  const Image image = framebuffer.read(false);
  const double read_ms = ms_since(start);
  const auto png = std::filesystem::temp_directory_path() / "nome_bench_render.png";
  start = Clock::now();
  write_png(png, image);
  const double png_ms = ms_since(start);
  std::filesystem::remove(png);
  const double first = frames.front();
  frames.erase(frames.begin());
  std::sort(frames.begin(), frames.end());
  std::printf(
      "%8u faces%s, %dx MSAA: display data %7.1f ms, upload %6.1f ms, first frame %7.1f ms, later frames "
      "median "
      "%7.1f ms, read-back %5.1f ms, PNG %6.1f ms\n",
      mesh.num_faces(), wire ? " + wire" : "       ", samples, build_ms, upload_ms, first,
      frames[frames.size() / 2], read_ms, png_ms);
}

}  // namespace

int main() {
  using namespace nome::render;
  {
    const auto start = Clock::now();
    const OffscreenContext context(Backend::osmesa);
    std::printf("%s: context %.1f ms\n", context.platform().c_str(), ms_since(start));
  }
  const auto start = Clock::now();
  const OffscreenContext context(Backend::egl);
  std::printf("%s (%s): context %.1f ms\n", context.platform().c_str(), context.description().c_str(),
              ms_since(start));
  const Renderer renderer;
  for (auto [u, v] : {std::pair<nome::Index, nome::Index>{48, 24}, {400, 250}, {1000, 500}}) {
    const nome::Mesh mesh = torus(u, v);
    for (int samples : {4, 0}) {
      measure(renderer, mesh, false, samples);
      measure(renderer, mesh, true, samples);
    }
  }
}

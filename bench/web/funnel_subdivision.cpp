// Catmull-Clark level 4 of the merged funnel cube on one thread, best of 7 wall times: built natively and
// by Emscripten for node, so that `make web-bench` prints the browser build's figure beside the desktop's.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene.hpp"

int main(int argc, char** argv) {
  using namespace nome;
  const std::string file = argc > 1 ? argv[1] : NOME_SOURCE_DIR "/assets/funnel_cube.nome";
  std::ostringstream text;
  text << std::ifstream(file).rdbuf();
  const scene::Scene scene = scene::Scene::from_text(text.str(), file);
  PipelineSettings settings;
  settings.stage = Stage::subdivided;
  settings.should_merge = true;
  settings.subdivision_levels = 4;
  settings.threads = 1;
  double best = 1e300;
  Index faces = 0;
  for (int run = 0; run < 7; ++run) {
    const auto start = std::chrono::steady_clock::now();
    Pipeline pipeline;
    pipeline.set_input(PipelineInput{scene.combined_soup(), {}, {}});
    faces = pipeline.run(settings).num_faces();
    best = std::min(
        best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("Catmull-Clark level 4 of the merged funnel cube, one thread: %u faces in %.2f ms\n", faces,
              best);
  return 0;
}

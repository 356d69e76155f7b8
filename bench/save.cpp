// Saving a document as .nome (the viewer's Save, its autosave and recovery file): the scene's statements
// and slider values and the document's edits as text, with no copy of the scene and no evaluation. Beside
// it, reading the document (one evaluation). CPU time, best of 5.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "nome/edit/scene_document.hpp"
#include "nome/scene/scene.hpp"

using namespace nome;

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

// A (3, 2) torus knot swept by a circle of 32 points along 10,000 samples: 320,000 quads.
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

// 4,096 funnels, each its own instance statement with its own transforms: 98,304 faces.
std::string funnel_field_scene() {
  std::string text = "bank b set h 1 0.5 2 0.1 endbank\nfunnel f (8 1 0.5 {expr $b_h}) endfunnel\n";
  for (int i = 0; i < 4096; ++i)
    text += "instance f" + std::to_string(i) + " f translate (" + std::to_string(3 * (i % 64)) + " " +
            std::to_string(3 * (i / 64)) + " 0) rotate (0 0 1) (" + std::to_string(i % 360) +
            ") endinstance\n";
  return text;
}

// A deleted face added back as a consolidated face and a sharp edge: every kind of edit a file keeps.
void edit(SceneDocument& doc) {
  Document& edits = doc.edits();
  const PolygonSoup& scene = edits.scene_geometry();
  std::vector<std::string> first;
  for (Index k = scene.face_offsets[0]; k < scene.face_offsets[1]; ++k)
    first.push_back(scene.vertex_names[scene.face_vertices[k]]);
  edits.delete_faces({scene.face_names[0]});
  edits.add_polygon(first);
  edits.accept_temporary();
  edits.set_sharp({{first[0], first[1]}}, 2.5f);
}

void figures(const char* name, const std::string& text) {
  const scene::SceneOptions for_document{.shows_edits = false};
  std::optional<SceneDocument> doc;
  std::printf("%s\n", name);
  std::printf(
      "  read into a document (one evaluation)          %8.2f\n", best_ms(5, [&] {
        doc.emplace(SceneDocument::from_scene(scene::Scene::from_text(text, "bench.nome", for_document)));
      }));
  edit(*doc);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "nome_bench_save.nome";
  std::printf("  save (and autosave): .nome written atomically   %8.3f\n",
              best_ms(5, [&] { doc->save(path); }));
  std::printf("  (%ju bytes; scene evaluations while saving: ",
              std::uintmax_t(std::filesystem::file_size(path)));
  const std::uint64_t before = scene::scene_evaluation_count();
  doc->save(path);
  std::printf("%ju)\n", std::uintmax_t(scene::scene_evaluation_count() - before));
  std::filesystem::remove(path);
}

}  // namespace

int main() {
  std::printf("Saving a document as .nome (ms, CPU, best of 5)\n");
  figures("swept knot, 320,000 quads", knot_scene());
  figures("4,096 funnel instances, 98,304 faces", funnel_field_scene());
}

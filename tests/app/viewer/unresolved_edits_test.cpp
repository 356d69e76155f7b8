#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_scene.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

// Two funnels whose vertex count is a slider, and a consolidated face on their sixth high-circle vertices.
std::string unresolved_two_funnels() {
  return "bank fb\n  set n 6 4 8 1\nendbank\n"
         "funnel f ({$fb_n} 1 0.5 1) endfunnel\n"
         "instance a f endinstance\n"
         "instance b f translate (4 0 0) endinstance\n"
         "consolidate\n"
         "  consolidateface vertex a_hc5 endvertex vertex b_hc5 endvertex vertex b_hc4 endvertex "
         "endconsolidateface\n"
         "endconsolidate\n";
}

}  // namespace

TEST_CASE(
    "a slider that removes an edit's vertices: the edit is listed, kept, restored, and save refuses "
    "meanwhile",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("unresolved_edits");
  std::ofstream(dir + "/funnels.nome") << unresolved_two_funnels();
  viewer::ViewerOptions options;
  options.file = dir + "/funnels.nome";
  options.script =
      nome::test::write_script(dir, "set fb_n 4\nsave " + dir + "/low.nome\nset fb_n 6\nsave " + dir +
                                        "/back.nome\naction lock-parameters\nset fb_n 5\nquit\n");
  nome::test::TestViewer viewer(options);
  // The unresolved edits the viewer's document holds, each time they change.
  std::vector<std::size_t> seen{0};
  int frames = 0;
  while (viewer.frame() && ++frames < 10000) {
    const Document* document = viewer.window().sessions().document();
    REQUIRE(document != nullptr);
    CHECK(document->consolidated_faces().size() == 1);  // kept throughout
    if (document->unresolved().size() != seen.back()) seen.push_back(document->unresolved().size());
  }
  CHECK(seen == std::vector<std::size_t>{0, 1, 0});
  const std::string log = viewer.messages();
  CHECK_THAT(log,
             Catch::Contains("warning: 1 edits lost their vertices at these slider values; kept, hidden") &&
                 Catch::Contains("edit1 (missing a_hc5 b_hc5 b_hc4)"));
  CHECK_THAT(log, Catch::Contains("save: refused, the file would lose 1 edits"));
  CHECK_FALSE(std::filesystem::exists(dir + "/low.nome"));
  CHECK_THAT(log, Catch::Contains("1 edits back with their vertices: edit1"));
  CHECK_THAT(log, Catch::Contains("set fb_n: the sliders are locked while editing"));
  CHECK(viewer.window().sessions().scene()->parameters().front().value == 6);
  CHECK(viewer.window().exit_status() == 1);  // the refused save and the locked slider failed

  // What was saved once the slider came back holds the edit, and reads back with it.
  const scene::Scene back = read_scene(dir + "/back.nome");
  REQUIRE(back.edits().consolidated.size() == 1);
  CHECK(back.edits().consolidated[0] == std::vector<std::string>{"a_hc5", "b_hc5", "b_hc4"});
}

#include <catch2/catch.hpp>

#include <fstream>
#include <memory>

#include "app/screen_oracle.hpp"
#include "app/viewer_support.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

// A funnel whose height slider moves its vertices and whose side count makes other faces.
const char* const funnel_text =
    "bank b\n  set h 0.5 0.1 1.5 0.1\n  set n 6 3 10 1\nendbank\n"
    "funnel f ({expr $b_n} 0.5 0.5 {expr $b_h}) endfunnel\n"
    "instance i f endinstance\n";

int count_of(const std::string& text, const std::string& part) {
  int count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

}  // namespace

TEST_CASE("a selection stays while a slider moves vertices and is cleared when the faces change", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("selection_change");
  std::ofstream(dir + "/funnel.nome") << funnel_text;
  const Mesh mesh = glue_faces(read_scene(dir + "/funnel.nome").combined_soup()).mesh;
  const ScreenProjection projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  std::optional<glm::dvec2> pixel;
  for (Index f = 0; f < mesh.num_faces() && !pixel; ++f) pixel = nome::test::face_click(mesh, projection, f);
  REQUIRE(pixel);

  const std::string cleared = "selection cleared: the displayed mesh changed its connectivity";
  // `view` after each change: its result is on screen before the next command.
  const auto run = [&](const std::string& changes) {
    viewer::ViewerOptions options;
    options.file = dir + "/funnel.nome";
    options.script = nome::test::write_script(
        dir, "view 30 25\nmode face\n" + nome::test::click_line(*pixel) + changes + "quit\n");
    auto viewer = std::make_unique<nome::test::TestViewer>(options);
    CHECK(viewer->run() == 0);
    CHECK(count_of(viewer->messages(), "face i_f") == 1);  // the click selected a face
    return viewer;
  };
  const auto moved = run("set b_h 0.7\nview 30 25\nset b_h 0.9\nview 30 25\n");
  CHECK(count_of(moved->messages(), cleared) == 0);
  CHECK_FALSE(moved->window().selection().is_empty());
  const auto remade = run("set b_n 8\nview 30 25\n");
  CHECK(count_of(remade->messages(), cleared) == 1);
  CHECK(remade->window().selection().is_empty());
}

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "render/image.hpp"

using namespace nome;
using nome::test::count_pixels;
using nome::test::run_viewer;
using nome::test::write_script;

// The real window, end to end: the `nome` binary under Xvfb (GLFW, ImGui's GL backend, the swap).
namespace {

using nome::test::assets;

using nome::test::obj_vertex;

using nome::test::click_line;

}  // namespace

TEST_CASE("without a display the viewer says so and points to nome render", "[app]") {
  const auto r = nome::test::run_nome_prefixed("env -u DISPLAY -u WAYLAND_DISPLAY", assets + "cube.obj");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("no display"));
  CHECK_THAT(r.err, Catch::Contains("nome render"));
}

TEST_CASE("a scripted session picks a vertex and a face, exports and takes a screenshot", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_cube");
  const Mesh mesh = build_mesh(read_polygons(assets + "cube.obj"));
  const auto projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  std::optional<glm::dvec2> vertex_click;
  Index picked = no_index;
  for (Index v = 0; v < mesh.num_vertices() && !vertex_click; ++v)
    if ((vertex_click = nome::test::vertex_click(mesh, projection, v))) picked = v;
  REQUIRE(vertex_click);
  const std::string script = write_script(dir,
                                          "view 30 25\n"
                                          "mode vertex\n" +
                                              click_line(*vertex_click) +
                                              "mode face\n"
                                              "click 640 400\n"
                                              "key W\n"
                                              "screenshot " +
                                              dir +
                                              "/cube.png\n"
                                              "export " +
                                              dir + "/cube.obj\nquit\n");
  const auto r = run_viewer(assets + "cube.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("vertex " + obj_vertex(picked) + " selected"));
  CHECK_THAT(r.err, Catch::Contains("face "));
  const render::Image shot = render::read_png(dir + "/cube.png");
  CHECK(shot.width == nome::test::viewer_width);
  CHECK(shot.height == nome::test::viewer_height);
  // ImGui's light panels and the white background are both on screen.
  CHECK(count_pixels(shot, 240, 240, 240, 3) > 20000);
  CHECK(count_pixels(shot, 255, 255, 255, 0) > 100000);
  CHECK(build_mesh(read_polygons(dir + "/cube.obj")).num_faces() == mesh.num_faces());
}

TEST_CASE(
    "quitting with unsaved changes asks first, in a prompt over the dimmed window, and save and quit saves",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_quit_prompt");
  std::filesystem::copy_file(assets + "funnel_cube.nome", dir + "/funnel_cube.nome");
  // No `quit`: the prompt's answer ends the session.
  const std::string script =
      write_script(dir, "set fp_n 6\nscreenshot " + dir + "/before.png\nkey Ctrl+Q\nscreenshot " + dir +
                            "/prompt.png\nprompt save\n");
  const auto r = run_viewer(dir + "/funnel_cube.nome --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("quit: the scene has unsaved changes"));
  const scene::Scene saved = read_scene(dir + "/funnel_cube.nome");
  CHECK(saved.parameters()[*saved.find_parameter("fp_n")].value == 6.0);
  // Ctrl+Q did not close the window: the prompt is up, and the modal dims the white background.
  const int white_before = count_pixels(render::read_png(dir + "/before.png"), 255, 255, 255, 0);
  const int white_prompt = count_pixels(render::read_png(dir + "/prompt.png"), 255, 255, 255, 0);
  CHECK(white_before > 100000);
  CHECK(white_prompt < white_before / 10);
}

// The panels open in the light theme (the layout's default) from the first frame, and the theme action
// turns them dark.
TEST_CASE("the panels open light and the theme action darkens them", "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_theme");
  const std::string script = write_script(
      dir, "screenshot " + dir + "/light.png\naction theme\nscreenshot " + dir + "/dark.png\nquit\n");
  const auto r = run_viewer(assets + "cube.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // The mean of the controls sidebar's left part, halfway down the window: its background and widgets.
  const auto sidebar_brightness = [](const render::Image& shot) {
    long sum = 0, count = 0;
    for (int y = shot.height / 2; y < shot.height / 2 + 100; ++y)
      for (int x = 2; x < 120; ++x, ++count) {
        const auto* p = shot.pixel(x, y);
        sum += (int(p[0]) + int(p[1]) + int(p[2])) / 3;
      }
    return sum / count;
  };
  CHECK(sidebar_brightness(render::read_png(dir + "/light.png")) > 200);
  CHECK(sidebar_brightness(render::read_png(dir + "/dark.png")) < 80);
}

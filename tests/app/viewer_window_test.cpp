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

// The Look panel's colours are steps of the undo history: a script changes one as the panel would, and
// undo and redo put it back and again.
TEST_CASE("a display colour is one undo step: background and default colour changed, undone and redone",
          "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_display_colors");
  const std::string script = write_script(
      dir, "display-color background 0 0 0\nscreenshot " + dir + "/black.png\naction undo\nscreenshot " +
               dir + "/undone.png\naction redo\nscreenshot " + dir +
               "/redone.png\ndisplay-color default 1 0 0\nscreenshot " + dir +
               "/red.png\naction undo\nscreenshot " + dir + "/gold.png\nquit\n");
  const auto r = run_viewer(assets + "cube.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto shot = [&](const char* name) { return render::read_png(dir + "/" + name + ".png"); };
  CHECK(count_pixels(shot("black"), 0, 0, 0, 0) > 100000);
  CHECK(count_pixels(shot("undone"), 0, 0, 0, 0) < 30000);  // the panels' text
  CHECK(count_pixels(shot("undone"), 255, 255, 255, 0) > 100000);
  CHECK(count_pixels(shot("redone"), 0, 0, 0, 0) > 100000);
  // The cube's lit faces: red while the default colour is red, gold again after undo.
  const auto reddish = [](const render::Image& image) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const auto* p = image.pixel(x, y);
        count += p[0] > 80 && p[1] < 20 && p[2] < 20;
      }
    return count;
  };
  CHECK(reddish(shot("red")) > 5000);
  CHECK(reddish(shot("gold")) < 100);
}

// An export the viewer cannot write says why in the log and fails the script's line; the rest still runs.
TEST_CASE("an export to a file the viewer cannot write is logged with the reason", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_export_refused");
  const std::string script = write_script(dir, "export " + dir + "/cube.xyz\nexport " + dir +
                                                   "/missing/cube.stl\nexport " + dir + "/cube.stl\nquit\n");
  const auto r = run_viewer(assets + "cube.obj --script " + script);
  INFO(r.err);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("error: export: the file must end in .stl, .obj, .glb or .ply, found '" +
                                    dir + "/cube.xyz'"));
  CHECK_THAT(r.err, Catch::Contains("script.txt:1: the command failed"));
  CHECK_THAT(r.err,
             Catch::Contains("missing/cube.stl") && Catch::Contains("script.txt:2: the command failed"));
  CHECK_FALSE(r.err.find("script.txt:3:") != std::string::npos);
  CHECK(std::filesystem::exists(dir + "/cube.stl"));
}

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer_support.hpp"
#include "viewer/window.hpp"

using namespace nome;
using nome::viewer::InputFrame;
using nome::viewer::KeyModifier;

// The window fed input as GLFW would feed it, in this process on the null renderer.
namespace {

using nome::test::assets;

InputFrame at(glm::dvec2 cursor) {
  InputFrame input;
  input.cursor = cursor;
  return input;
}

// A press in one frame and the release in the next, without moving: a click.
void click(nome::test::TestViewer& viewer, glm::dvec2 pixel, int button = 0, bool is_double = false) {
  InputFrame press = at(pixel);
  press.is_pressed[button] = press.is_down[button] = true;
  press.is_double_click = is_double;
  viewer.frame(press);
  viewer.frame(at(pixel));
}

void press_key(nome::test::TestViewer& viewer, int key, KeyModifier modifiers = KeyModifier::none) {
  InputFrame input;
  input.keys.push_back({key, modifiers});
  viewer.frame(input);
}

bool has_message(const nome::test::TestViewer& viewer, const std::string& text) {
  return viewer.messages().find(text) != std::string::npos;
}

}  // namespace

TEST_CASE("the window takes clicks, drags, the wheel and keys as input frames", "[app]") {
  viewer::ViewerOptions options;
  options.file = assets + "cube.obj";
  nome::test::TestViewer viewer(options);
  viewer::Window& window = viewer.window();
  REQUIRE(window.shown());
  CHECK(viewer.platform().title() == "Nome - cube.obj");

  // The window opens looking from the default angles, so the test's camera finds the pixel of a vertex.
  const Mesh& cube = *window.shown()->mesh;
  const auto projection = nome::test::viewer_projection(cube, 30.0, 25.0);
  std::optional<glm::dvec2> pixel;
  Index v = 0;
  for (; v < cube.num_vertices() && !pixel; ++v) pixel = nome::test::vertex_click(cube, projection, v);
  REQUIRE(pixel);
  click(viewer, *pixel);
  REQUIRE(window.selection().vertices().size() == 1);
  CHECK(window.selection().vertices()[0] == v - 1);

  SECTION("a right click clears the selection; a press over a panel picks nothing") {
    click(viewer, *pixel, 1);
    CHECK(window.selection().is_empty());
    InputFrame press = at(*pixel);
    press.is_pressed[0] = press.is_down[0] = true;
    press.is_over_panel = true;
    viewer.frame(press);
    viewer.frame(at(*pixel));
    CHECK(window.selection().is_empty());
  }
  SECTION("a drag turns the camera and selects nothing; the wheel zooms") {
    const auto before = window.camera().orientation;
    InputFrame press = at({600, 400});
    press.is_pressed[0] = press.is_down[0] = true;
    viewer.frame(press);
    for (double x = 610; x <= 700; x += 10) {
      InputFrame move = at({x, 400});
      move.is_down[0] = true;
      viewer.frame(move);
    }
    viewer.frame(at({700, 400}));
    CHECK(window.camera().orientation != before);
    CHECK(window.selection().vertices().size() == 1);
    const double distance = window.camera().distance;
    InputFrame wheel = at({700, 400});
    wheel.wheel = 1.0;
    viewer.frame(wheel);
    CHECK(window.camera().distance < distance);
  }
  SECTION("a double-click orbits around the surface point") {
    click(viewer, {640, 400}, 0, true);
    CHECK(has_message(viewer, "orbit centre at ("));
  }
  SECTION("keys run the actions of the table; Ctrl+Q without changes closes") {
    press_key(viewer, GLFW_KEY_W);
    CHECK_FALSE(window.display().draws_faces);
    CHECK(window.display().draws_wireframe);
    press_key(viewer, GLFW_KEY_SLASH, KeyModifier::shift);
    CHECK(window.panels().is_help_shown);
    press_key(viewer, GLFW_KEY_Z, KeyModifier::control);
    CHECK(has_message(viewer, "undo: nothing to undo"));
    press_key(viewer, GLFW_KEY_ESCAPE);
    CHECK(window.selection().is_empty());
    InputFrame quit;
    quit.keys.push_back({GLFW_KEY_Q, KeyModifier::control});
    CHECK_FALSE(viewer.frame(quit));
  }
}

TEST_CASE("the null renderer refuses a screenshot, which fails a scripted session", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_null_screenshot");
  std::ofstream(dir + "/script.txt") << "screenshot " << dir << "/shot.png\nquit\n";
  const auto r = nome::test::run_window(assets + "cube.obj --script " + dir + "/script.txt");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("screenshot: the null renderer draws no picture"));
  CHECK_FALSE(std::filesystem::exists(dir + "/shot.png"));
}

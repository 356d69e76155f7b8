#include <catch2/catch.hpp>

#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer_support.hpp"
#include "viewer/tools/turntable_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

TEST_CASE("the viewer's turntable (T) turns the view about the vertical axis until it is turned off",
          "[app]") {
  viewer::ViewerOptions options;
  options.file = std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome";
  test::TestViewer viewer(options);
  for (int i = 0; i < 4; ++i) viewer.frame();
  viewer::InputFrame press;
  press.keys.push_back({GLFW_KEY_T, viewer::KeyModifier::none});
  viewer.frame(press);
  REQUIRE(viewer.window().find_tool<viewer::TurntableTool>()->is_on());
  CHECK(viewer.window().is_animating());
  const glm::dvec3 eye = viewer.window().camera().eye() - viewer.window().camera().target;
  // A second of frames (each frame moves the test clock a sixtieth of a second): a twelfth of a turn,
  // 30 degrees, about +Y (the height of the eye stays).
  for (int i = 0; i < 60; ++i) viewer.frame();
  const glm::dvec3 turned = viewer.window().camera().eye() - viewer.window().camera().target;
  CHECK(turned.y == Approx(eye.y));
  const double angle = std::atan2(turned.x, turned.z) - std::atan2(eye.x, eye.z);
  CHECK(std::remainder(angle, 2 * M_PI) == Approx(M_PI / 6).epsilon(0.05));
  viewer.frame(press);
  CHECK_FALSE(viewer.window().find_tool<viewer::TurntableTool>()->is_on());
  const glm::dvec3 stopped = viewer.window().camera().eye();
  viewer.frame();
  CHECK(viewer.window().camera().eye() == stopped);
}

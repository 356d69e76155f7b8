// What the window reads of a frame's mouse and keys from ImGui (read_imgui_input), on a context of the
// test's own with no window behind it (OwnImGuiContext).
#include <catch2/catch.hpp>

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer/imgui_text.hpp"
#include "viewer/platform.hpp"

using namespace nome::viewer;

namespace {

// One frame with the context's present input; returns what the window reads of it.
InputFrame frame() {
  ImGui::NewFrame();
  InputFrame input = read_imgui_input();
  ImGui::EndFrame();
  return input;
}

}  // namespace

TEST_CASE("a frame's input is read where the mouse is, with its buttons, wheel and keys", "[app]") {
  const nome::test::OwnImGuiContext context;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(123.0f, 456.0f);  // ImGui keeps whole pixels
  InputFrame idle = frame();
  CHECK(idle.cursor == glm::dvec2(123.0, 456.0));
  CHECK_FALSE(idle.is_down[0]);
  CHECK_FALSE(idle.is_pressed[0]);
  io.MousePos = ImVec2(300.0f, 200.0f);
  io.MouseDown[1] = true;
  io.MouseWheel = 2.0f;
  const InputFrame pressed = frame();
  CHECK(pressed.cursor == glm::dvec2(300.0, 200.0));
  CHECK(pressed.is_pressed[1]);
  CHECK(pressed.is_down[1]);
  CHECK_FALSE(pressed.is_down[0]);
  CHECK(pressed.wheel == 2.0);
  io.MouseWheel = 0.0f;
  const InputFrame held = frame();
  CHECK_FALSE(held.is_pressed[1]);  // went down in the frame before
  CHECK(held.is_down[1]);
  io.MouseDown[1] = false;
  io.KeysDown[GLFW_KEY_W] = true;
  io.KeyCtrl = true;
  const InputFrame key = frame();
  REQUIRE(key.keys.size() == 1);
  CHECK(key.keys[0].key == GLFW_KEY_W);
  CHECK(key.keys[0].modifiers == KeyModifier::control);
  CHECK_FALSE(key.is_over_panel);
}

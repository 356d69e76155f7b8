#include <imgui.h>

#include "viewer/platform.hpp"

namespace nome::viewer {

InputFrame read_imgui_input() {
  const ImGuiIO& io = ImGui::GetIO();
  InputFrame input;
  input.cursor = {io.MousePos.x, io.MousePos.y};
  for (int button = 0; button < 3; ++button) {
    input.is_pressed[button] = ImGui::IsMouseClicked(button);
    input.is_down[button] = ImGui::IsMouseDown(button);
  }
  input.is_double_click = ImGui::IsMouseDoubleClicked(0);
  input.wheel = io.MouseWheel;
  input.is_over_panel = io.WantCaptureMouse;
  if (io.WantCaptureKeyboard) return input;
  const KeyModifier modifiers = (io.KeyShift ? KeyModifier::shift : KeyModifier::none) |
                                (io.KeyCtrl ? KeyModifier::control : KeyModifier::none);
  input.held = modifiers;
  // ImGui 1.86 indexes its key state by the platform's key codes (GLFW's here).
  for (int key = 0; key < IM_ARRAYSIZE(io.KeysDown); ++key)
    if (ImGui::IsKeyPressed(key, false)) input.keys.push_back({key, modifiers});
  return input;
}

}  // namespace nome::viewer

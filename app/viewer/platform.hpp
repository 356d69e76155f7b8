#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "viewer/commands/actions.hpp"

namespace nome::viewer {

struct KeyPress {
  int key = 0;  // a GLFW key code
  KeyModifier modifiers = KeyModifier::none;
};

// One frame's input, as the window reads it: from GLFW through ImGui (read_imgui_input), or made by a
// test. Buttons: 0 left, 1 right, 2 middle.
struct InputFrame {
  glm::dvec2 cursor{0.0};            // window pixels, origin top-left
  std::array<bool, 3> is_pressed{};  // went down this frame
  std::array<bool, 3> is_down{};
  bool is_double_click = false;  // the left press of this frame is the second of a double-click
  double wheel = 0.0;
  bool is_over_panel = false;            // a panel takes the mouse: no camera moves or picks start
  std::vector<KeyPress> keys;            // pressed this frame and not taken by a panel's text field
  KeyModifier held = KeyModifier::none;  // the modifier keys held now
};

// The window system under the viewer: a GLFW window, or a test's fixed-size one with its own clock.
class Platform {
 public:
  virtual ~Platform() = default;
  // In the cursor's units (screen coordinates).
  virtual glm::dvec2 window_size() const = 0;
  virtual glm::ivec2 framebuffer_size() const = 0;
  // Seconds of a steady clock.
  virtual double now() const = 0;
  virtual void set_title(const std::string& title) = 0;
  // The monitor's scale for text and sizes (HiDPI: 2 on a screen of twice the usual density).
  virtual float content_scale() const = 0;
  // Where files live outside the program's own file system (a web page: the user's disk), the platform
  // shows its own picker for File > Open and returns true; false leaves it to the window's file dialog.
  virtual bool pick_file_to_open() { return false; }
  // A file the user just saved or exported: a web page offers it as a download; on a desktop it is on
  // disk already.
  virtual void offer_saved_file(const std::filesystem::path&) {}
};

// This frame's input from ImGui's IO (which its GLFW backend fills); needs a frame begun.
InputFrame read_imgui_input();

}  // namespace nome::viewer

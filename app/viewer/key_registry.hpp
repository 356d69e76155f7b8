#pragma once

#include <functional>
#include <string>
#include <vector>

namespace nome::viewer {

// Modifier bits, the same values as GLFW's (GLFW_MOD_SHIFT, GLFW_MOD_CONTROL) so the window passes its
// own through; the registry itself needs no GLFW.
enum KeyModifier : int { shift = 0x1, control = 0x2 };

// One shortcut: the key (a GLFW key code), its modifiers, the label the help overlay and the script's
// `key` command use ("W", "Ctrl+Z", "F1"), what it does in words, and the action.
struct KeyBinding {
  int key = 0;
  int modifiers = 0;
  std::string label;
  std::string description;
  std::function<void()> action;
};

// Every keyboard shortcut of the viewer in one place (pmp-library's help registry): the keyboard, the
// `?` / F1 overlay and scripts all read it, so they cannot disagree.
class KeyRegistry {
 public:
  // Adds a binding; the label is derived from key and modifiers.
  void add(int key, int modifiers, std::string description, std::function<void()> action);

  // Runs the binding of this key press; false when there is none.
  bool press(int key, int modifiers) const;
  // Runs the binding with this label (case-insensitive: "w", "ctrl+z"); false when there is none.
  bool press(const std::string& label) const;

  const std::vector<KeyBinding>& bindings() const { return bindings_; }

 private:
  std::vector<KeyBinding> bindings_;
};

// "Ctrl+Shift+F1", "W", "?" from a GLFW key code and modifiers.
std::string key_label(int key, int modifiers);

}  // namespace nome::viewer

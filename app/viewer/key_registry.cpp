#include "viewer/key_registry.hpp"

#include <algorithm>
#include <cctype>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>

namespace nome::viewer {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string key_name(int key) {
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + key - GLFW_KEY_A));
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  switch (key) {
    case GLFW_KEY_SLASH:
      return "/";
    case GLFW_KEY_ESCAPE:
      return "Esc";
    case GLFW_KEY_DELETE:
      return "Delete";
    case GLFW_KEY_ENTER:
      return "Enter";
    case GLFW_KEY_SPACE:
      return "Space";
    case GLFW_KEY_KP_1:
      return "Keypad1";
    case GLFW_KEY_KP_3:
      return "Keypad3";
    case GLFW_KEY_KP_7:
      return "Keypad7";
    default:
      return "Key" + std::to_string(key);
  }
}

}  // namespace

std::string key_label(int key, int modifiers) {
  // Shift+/ is how '?' is typed on the keyboards we know; show it as the user thinks of it.
  if (key == GLFW_KEY_SLASH && modifiers == KeyModifier::shift) return "?";
  std::string label;
  if (modifiers & KeyModifier::control) label += "Ctrl+";
  if (modifiers & KeyModifier::shift) label += "Shift+";
  return label + key_name(key);
}

void KeyRegistry::add(int key, int modifiers, std::string description, std::function<void()> action) {
  bindings_.push_back({key, modifiers, key_label(key, modifiers), std::move(description), std::move(action)});
}

bool KeyRegistry::press(int key, int modifiers) const {
  modifiers &= KeyModifier::shift | KeyModifier::control;
  for (const KeyBinding& b : bindings_) {
    if (b.key != key || b.modifiers != modifiers) continue;
    b.action();
    return true;
  }
  return false;
}

bool KeyRegistry::press(const std::string& label) const {
  const std::string wanted = lower(label);
  for (const KeyBinding& b : bindings_) {
    if (lower(b.label) != wanted) continue;
    b.action();
    return true;
  }
  return false;
}

}  // namespace nome::viewer

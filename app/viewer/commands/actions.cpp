#include "viewer/commands/actions.hpp"

#include <algorithm>
#include <cctype>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>

namespace nome::viewer {
namespace {

using enum Action;
constexpr KeyModifier none = KeyModifier::none;
constexpr KeyModifier shift = KeyModifier::shift;
constexpr KeyModifier control = KeyModifier::control;

// In the help overlay's order; the actions without a key last.
const ActionInfo table[] = {
    {toggle_help, "help", GLFW_KEY_SLASH, shift, "show or hide this help"},
    {toggle_help, "help", GLFW_KEY_F1, none, "show or hide this help"},
    {open, "open", GLFW_KEY_O, control, "open a file"},
    {open_recent_1, "open-recent-1", GLFW_KEY_1, control, "open recent file 1"},
    {open_recent_2, "open-recent-2", GLFW_KEY_2, control, "open recent file 2"},
    {open_recent_3, "open-recent-3", GLFW_KEY_3, control, "open recent file 3"},
    {open_recent_4, "open-recent-4", GLFW_KEY_4, control, "open recent file 4"},
    {save, "save", GLFW_KEY_S, control, "save the scene (.nome)"},
    {save_as, "save-as", GLFW_KEY_S, control | shift, "save the scene as (.nome)"},
    {export_mesh, "export", GLFW_KEY_E, control, "export the stage on screen (.stl, .obj, .glb, .ply)"},
    {quit, "quit", GLFW_KEY_Q, control, "quit"},
    {zoom_in, "zoom-in", GLFW_KEY_I, none, "zoom in"},
    {zoom_out, "zoom-out", GLFW_KEY_O, none, "zoom out"},
    {toggle_faces, "wireframe", GLFW_KEY_W, none, "wire mode / polygon mode"},
    {toggle_shading, "shading", GLFW_KEY_S, none, "shading: automatic / smooth / flat"},
    {toggle_culling, "culling", GLFW_KEY_X, none, "back-face culling on / off"},
    {frame_all, "frame", GLFW_KEY_F, none, "frame everything"},
    {reset_view, "reset-view", GLFW_KEY_H, control, "reset the view"},
    {view_front, "view-front", GLFW_KEY_KP_1, none, "view from the front"},
    {view_right, "view-right", GLFW_KEY_KP_3, none, "view from the right"},
    {view_top, "view-top", GLFW_KEY_KP_7, none, "view from the top"},
    {screenshot, "screenshot", GLFW_KEY_P, none, "save a screenshot PNG"},
    {toggle_turntable, "turntable", GLFW_KEY_T, none, "spin the model about the vertical axis (on / off)"},
    {measure_distance, "measure-distance", GLFW_KEY_M, none, "measure: clicks give distances (on / off)"},
    {toggle_section, "section", GLFW_KEY_C, none, "section plane on / off (Section: its normal, position)"},
    {measure_wall, "measure-wall", GLFW_KEY_M, shift, "measure: a click gives the solid's wall (on / off)"},
    {toggle_log, "log", GLFW_KEY_L, none, "open or collapse the log"},
    {toggle_text_pane, "text", GLFW_KEY_T, control, "show or hide the scene text pane"},
    {apply_text, "apply-text", GLFW_KEY_ENTER, control,
     "evaluate the text pane's text (the geometry keeps on error)"},
    {save_text, "save-text", 0, none, "save the text pane's text as the file (Ctrl+S while typing in it)"},
    {toggle_sidebars, "sidebars", GLFW_KEY_TAB, none, "hide or show both sidebars"},
    {toggle_theme, "theme", 0, none, "dark or light theme"},
    {undo, "undo", GLFW_KEY_Z, control, "undo"},
    {redo, "redo", GLFW_KEY_Y, control, "redo"},
    {add_polygon, "add-polygon", GLFW_KEY_ENTER, none, "add a polygon through the selected vertices"},
    {accept, "accept", GLFW_KEY_A, control, "accept the temporary faces (consolidate)"},
    {delete_faces, "delete", GLFW_KEY_DELETE, none, "delete the selected faces"},
    {toggle_sharp, "sharp", GLFW_KEY_K, none, "mark the selected edges sharp (smooth if all are sharp)"},
    {move, "move", GLFW_KEY_G, none,
     "drag the selected vertices or instances: X/Y/Z an axis (Shift: across it), Ctrl the grid, a number "
     "that far; click or Enter keeps, Esc or right click cancels"},
    {clear_selection, "clear-selection", GLFW_KEY_ESCAPE, none, "clear the selection"},
    {clear_temporary, "clear", 0, none, "clear the temporary faces"},
    {zip, "zip", 0, none, "zip the two selected borders"},
    {merge, "merge", 0, none, "show the merged stage"},
    {toggle_parameter_lock, "lock-parameters", 0, none, "lock generator parameters while editing (on / off)"},
    {toggle_sif_pairing, "pair-triangles", 0, none, "pair a .sif file's triangles into quads (on / off)"},
    {print_check, "print-check", 0, none, "check the offset for printing now (Print check section)"},
    {next_print_place, "next-print-place", 0, none, "frame the next place the print check lists"},
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string key_name(int key) {
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + key - GLFW_KEY_A));
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) return "Keypad" + std::to_string(key - GLFW_KEY_KP_0);
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
    case GLFW_KEY_TAB:
      return "Tab";
    default:
      return "Key" + std::to_string(key);
  }
}

bool has(KeyModifier modifiers, KeyModifier bit) {
  return (int(modifiers) & int(bit)) != 0;
}

}  // namespace

std::span<const ActionInfo> action_table() {
  return table;
}

std::optional<Action> find_action(std::string_view name) {
  for (const ActionInfo& row : table)
    if (name == row.name) return row.action;
  return std::nullopt;
}

std::string action_name(Action action) {
  for (const ActionInfo& row : table)
    if (row.action == action) return row.name;
  return {};
}

std::string action_names() {
  // The rows of one action are neighbours: each name once.
  std::string names = table[0].name;
  for (std::size_t i = 1; i < std::size(table); ++i)
    if (table[i].action != table[i - 1].action) names += std::string(", ") + table[i].name;
  return names;
}

std::string shortcut(Action action) {
  for (const ActionInfo& row : table)
    if (row.action == action && row.key != 0) return key_label(row.key, row.modifiers);
  return {};
}

std::string key_label(int key, KeyModifier modifiers) {
  // Shift+/ is how '?' is typed on the keyboards we know; show it as the user thinks of it.
  if (key == GLFW_KEY_SLASH && modifiers == KeyModifier::shift) return "?";
  std::string label;
  if (has(modifiers, KeyModifier::control)) label += "Ctrl+";
  if (has(modifiers, KeyModifier::shift)) label += "Shift+";
  return label + key_name(key);
}

std::optional<std::pair<int, KeyModifier>> key_of_label(const std::string& label) {
  const std::string wanted = lower(label);
  for (const KeyModifier m : {KeyModifier::none, KeyModifier::shift, KeyModifier::control,
                              KeyModifier::control | KeyModifier::shift})
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key)
      if (lower(key_label(key, m)) == wanted) return std::pair{key, m};
  return std::nullopt;
}

void ActionRegistry::bind(Action action, Handler handler) {
  if (handlers_.size() <= std::size_t(action)) handlers_.resize(std::size_t(action) + 1);
  handlers_[std::size_t(action)] = std::move(handler);
}

bool ActionRegistry::run(Action action) const {
  const std::size_t i = std::size_t(action);
  return i < handlers_.size() && handlers_[i] && handlers_[i]();
}

bool ActionRegistry::press(int key, KeyModifier modifiers) const {
  modifiers = KeyModifier(int(modifiers) & int(KeyModifier::shift | KeyModifier::control));
  for (const ActionInfo& row : table) {
    if (row.key == 0 || row.key != key || row.modifiers != modifiers) continue;
    run(row.action);
    return true;
  }
  for (std::size_t i = 0; i < tool_commands_.size(); ++i) {
    const ToolCommandInfo& row = tool_commands_[i];
    if (row.key == 0 || row.key != key || row.modifiers != modifiers) continue;
    tool_handlers_[i]();
    return true;
  }
  return false;
}

bool ActionRegistry::press(const std::string& label) const {
  const std::string wanted = lower(label);
  for (const ActionInfo& row : table) {
    if (row.key == 0 || lower(key_label(row.key, row.modifiers)) != wanted) continue;
    run(row.action);
    return true;
  }
  for (std::size_t i = 0; i < tool_commands_.size(); ++i) {
    const ToolCommandInfo& row = tool_commands_[i];
    if (row.key == 0 || lower(key_label(row.key, row.modifiers)) != wanted) continue;
    tool_handlers_[i]();
    return true;
  }
  return false;
}

void ActionRegistry::add(ToolCommandInfo info, Handler handler) {
  tool_commands_.push_back(std::move(info));
  tool_handlers_.push_back(std::move(handler));
}

std::optional<bool> ActionRegistry::run_tool_command(const std::string& name) const {
  for (std::size_t i = 0; i < tool_commands_.size(); ++i)
    if (tool_commands_[i].name == name) return tool_handlers_[i]();
  return std::nullopt;
}

}  // namespace nome::viewer

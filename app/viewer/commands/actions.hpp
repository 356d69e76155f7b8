#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace nome::viewer {

// Modifier bits, the same values as GLFW's (GLFW_MOD_SHIFT, GLFW_MOD_CONTROL) so the window passes its
// own through; the registry itself needs no GLFW.
enum class KeyModifier : int { none = 0, shift = 0x1, control = 0x2 };

constexpr KeyModifier operator|(KeyModifier a, KeyModifier b) {
  return KeyModifier(int(a) | int(b));
}

// Everything a user can ask of the viewer by a key, a menu item, a button or a script's `action NAME`.
enum class Action {
  add_polygon,
  accept,
  clear_temporary,
  delete_faces,
  zip,
  merge,
  undo,
  redo,
  clear_selection,
  toggle_help,
  open,
  open_recent_1,
  open_recent_2,
  open_recent_3,
  open_recent_4,
  save,
  save_as,
  export_mesh,
  quit,
  zoom_in,
  zoom_out,
  toggle_faces,
  toggle_shading,
  toggle_culling,
  frame_all,
  reset_view,
  view_front,
  view_right,
  view_top,
  screenshot,
  toggle_log,
  toggle_sidebars,
  toggle_theme,
  toggle_parameter_lock,
  toggle_sif_pairing,
  toggle_sharp,
  move,
  toggle_turntable,
  measure_distance,
  measure_wall,
  toggle_section,
  print_check,
  next_print_place,
  toggle_text_pane,
  apply_text,
  save_text,
};

// One row of the table every binding is read from: the script's name, a shortcut (key 0: none; an
// action may have several rows, one per key) and the help overlay's words.
struct ActionInfo {
  Action action;
  const char* name;
  int key;  // a GLFW key code
  KeyModifier modifiers;
  const char* description;
};

// The one table (pmp-library's help registry): keyboard, menus, buttons, scripts and the help overlay
// all read it, so they cannot disagree.
std::span<const ActionInfo> action_table();
// The action of a script name ("zip", "add-polygon"); none for an unknown one.
std::optional<Action> find_action(std::string_view name);
// The script name of the action ("add-polygon").
std::string action_name(Action action);
// Every script name, comma-separated, for messages.
std::string action_names();
// The label of the action's first shortcut ("Ctrl+Z"), empty when it has none.
std::string shortcut(Action action);
// "Ctrl+Shift+F1", "W", "?" from a GLFW key code and modifiers.
std::string key_label(int key, KeyModifier modifiers);
// The key code and modifiers of a label as key_label writes it (case-insensitive); none for another text.
std::optional<std::pair<int, KeyModifier>> key_of_label(const std::string& label);

// A command a tool adds beside the table's: its script name (`tool NAME`), its key (0: none) and the help
// overlay's words.
struct ToolCommandInfo {
  std::string name;
  int key = 0;  // a GLFW key code
  KeyModifier modifiers = KeyModifier::none;
  std::string description;
};

// What each action does in this window: keys and labels are looked up in the table, then in the tools'
// commands.
class ActionRegistry {
 public:
  // The handler returns false when it refused (and logged why).
  using Handler = std::function<bool()>;

  void bind(Action action, Handler handler);
  // Runs the action; false when it was refused or nothing is bound to it.
  bool run(Action action) const;
  // Runs the action of this key press (Alt and other modifiers ignored); false when no key is bound.
  bool press(int key, KeyModifier modifiers) const;
  // Runs the action with this shortcut label (case-insensitive: "w", "ctrl+z"); false when none has it.
  bool press(const std::string& label) const;

  // A tool's own command; a key the table has already stays the table's.
  void add(ToolCommandInfo info, Handler handler);
  // Runs the tool command of this name; none when no tool has it, else whether it did its work.
  std::optional<bool> run_tool_command(const std::string& name) const;
  const std::vector<ToolCommandInfo>& tool_commands() const { return tool_commands_; }

 private:
  std::vector<Handler> handlers_;
  std::vector<ToolCommandInfo> tool_commands_;
  std::vector<Handler> tool_handlers_;  // by tool command
};

}  // namespace nome::viewer

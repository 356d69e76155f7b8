#include "viewer/panels/menu_sink.hpp"
#include "viewer/panels/panels.hpp"

namespace nome::viewer {
namespace {

// A menu item that runs an action, showing its shortcut from the table.
void action_item(MenuSink& menus, const ActionRegistry& actions, const char* label, Action action,
                 bool is_enabled = true) {
  if (menus.item(label, shortcut(action), false, is_enabled)) actions.run(action);
}

std::optional<std::filesystem::path> draw_file_menu(MenuSink& menus, const ActionRegistry& actions,
                                                    const MenuContext& context) {
  std::optional<std::filesystem::path> chosen;
  action_item(menus, actions, "Open...", Action::open);
  if (menus.begin_menu("Open Recent", !context.recent.files().empty())) {
    const auto& files = context.recent.files();
    for (std::size_t i = 0; i < files.size() && !chosen; ++i) {
      const std::string keys = i < 4 ? "Ctrl+" + std::to_string(i + 1) : "";
      if (menus.item(files[i].string().c_str(), keys)) chosen = files[i];
    }
    menus.end_menu();
  }
  action_item(menus, actions, "Save", Action::save, context.has_scene);
  action_item(menus, actions, "Save As...", Action::save_as, context.has_scene);
  action_item(menus, actions, "Export STL / OBJ / glTF / PLY...", Action::export_mesh, context.has_document);
  action_item(menus, actions, "Screenshot", Action::screenshot);
  menus.separator();
  action_item(menus, actions, "Quit", Action::quit);
  return chosen;
}

void draw_view_menu(MenuSink& menus, const ActionRegistry& actions, render::DisplaySettings& display,
                    LayoutSettings& layout) {
  if (menus.toggle("Faces", shortcut(Action::toggle_faces), display.draws_faces) && !display.draws_faces)
    display.draws_wireframe = true;
  menus.toggle("Wireframe overlay", "", display.draws_wireframe);
  if (menus.begin_menu("Shading")) {
    if (menus.item("Automatic: flat until subdivided", "", display.shading == render::Shading::automatic))
      display.shading = render::Shading::automatic;
    if (menus.item("Smooth", "", display.shading == render::Shading::smooth))
      display.shading = render::Shading::smooth;
    if (menus.item("Flat", "", display.shading == render::Shading::flat))
      display.shading = render::Shading::flat;
    menus.note(shortcut(Action::toggle_shading) + " cycles them");
    menus.end_menu();
  }
  bool is_culled = display.back_faces == render::BackFacePolicy::cull;
  if (menus.toggle("Back-face culling", shortcut(Action::toggle_culling), is_culled))
    display.back_faces = is_culled ? render::BackFacePolicy::cull : render::BackFacePolicy::different;
  bool is_back_colored = display.back_faces == render::BackFacePolicy::different;
  if (menus.toggle("Back faces in their own colour", "", is_back_colored))
    display.back_faces = is_back_colored ? render::BackFacePolicy::different : render::BackFacePolicy::same;
  menus.toggle("Möbius edges", "", display.draws_mobius_edges);
  menus.toggle("Borders", "", display.draws_borders);
  menus.toggle("Instance colours", "", display.uses_face_colors);
  menus.toggle("The scene's lights", "", display.uses_scene_lights);
  if (menus.begin_menu("Palette")) {
    const render::DisplaySettings plain;
    if (menus.item("Nome: gold front, blue back", "")) {
      display.front_color = plain.front_color;
      display.back_color = plain.back_color;
      display.back_faces = render::BackFacePolicy::different;
    }
    if (menus.item("JIPCAD: orange front, dark grey back", "")) render::use_jipcad_palette(display);
    menus.end_menu();
  }
  menus.separator();
  action_item(menus, actions, "Frame all", Action::frame_all);
  action_item(menus, actions, "Section plane", Action::toggle_section);
  action_item(menus, actions, "Reset view", Action::reset_view);
  action_item(menus, actions, "Turntable", Action::toggle_turntable);
  action_item(menus, actions, "Front", Action::view_front);
  action_item(menus, actions, "Right", Action::view_right);
  action_item(menus, actions, "Top", Action::view_top);
  menus.separator();
  menus.toggle("Controls sidebar", "", layout.is_left_shown);
  menus.toggle("Parameters sidebar", "", layout.is_right_shown);
  action_item(menus, actions, "Hide / show both sidebars", Action::toggle_sidebars);
  menus.toggle("Log open", shortcut(Action::toggle_log), layout.is_log_open);
  menus.toggle("Scene text", shortcut(Action::toggle_text_pane), layout.is_pane_shown);
  menus.toggle("Dark theme", "", layout.is_dark);
}

}  // namespace

std::optional<std::filesystem::path> draw_main_menu(MenuSink& menus, const ActionRegistry& actions,
                                                    const MenuContext& context,
                                                    render::DisplaySettings& display,
                                                    LayoutSettings& layout) {
  if (!menus.begin_bar()) return std::nullopt;
  std::optional<std::filesystem::path> chosen;
  if (menus.begin_menu("File")) {
    chosen = draw_file_menu(menus, actions, context);
    menus.end_menu();
  }
  if (menus.begin_menu("Edit")) {
    action_item(menus, actions, "Undo", Action::undo, context.can_undo);
    action_item(menus, actions, "Redo", Action::redo, context.can_redo);
    action_item(menus, actions, "Move the selection", Action::move, context.has_scene);
    menus.end_menu();
  }
  if (menus.begin_menu("View")) {
    draw_view_menu(menus, actions, display, layout);
    menus.end_menu();
  }
  // Commands the tools add beyond the action table: reachable without their keys.
  if (!actions.tool_commands().empty() && menus.begin_menu("Tools")) {
    for (const ToolCommandInfo& command : actions.tool_commands()) {
      const std::string key = command.key != 0 ? key_label(command.key, command.modifiers) : std::string();
      if (menus.item(command.description.c_str(), key)) actions.run_tool_command(command.name);
    }
    menus.end_menu();
  }
  if (menus.begin_menu("Help")) {
    action_item(menus, actions, "Keys and mouse", Action::toggle_help);
    menus.end_menu();
  }
  menus.end_bar();
  return chosen;
}

}  // namespace nome::viewer

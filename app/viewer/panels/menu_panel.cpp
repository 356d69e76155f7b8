#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {
namespace {

// A menu item that runs an action, showing its shortcut from the table.
void action_item(const ActionRegistry& actions, const char* label, Action action, bool is_enabled = true) {
  if (ImGui::MenuItem(label, shortcut(action).c_str(), false, is_enabled)) actions.run(action);
}

std::optional<std::filesystem::path> draw_file_menu(const ActionRegistry& actions,
                                                    const MenuContext& context) {
  std::optional<std::filesystem::path> chosen;
  action_item(actions, "Open...", Action::open);
  if (ImGui::BeginMenu("Open Recent", !context.recent.files().empty())) {
    const auto& files = context.recent.files();
    for (std::size_t i = 0; i < files.size() && !chosen; ++i) {
      const std::string keys = i < 4 ? "Ctrl+" + std::to_string(i + 1) : "";
      if (ImGui::MenuItem(files[i].string().c_str(), keys.c_str())) chosen = files[i];
    }
    ImGui::EndMenu();
  }
  action_item(actions, "Save", Action::save, context.has_scene);
  action_item(actions, "Save As...", Action::save_as, context.has_scene);
  action_item(actions, "Export STL / OBJ / glTF / PLY...", Action::export_mesh, context.has_document);
  action_item(actions, "Screenshot", Action::screenshot);
  ImGui::Separator();
  action_item(actions, "Quit", Action::quit);
  return chosen;
}

void draw_view_menu(const ActionRegistry& actions, render::DisplaySettings& display, LayoutSettings& layout) {
  bool is_wire = display.draws_wireframe;
  if (ImGui::MenuItem("Faces", shortcut(Action::toggle_faces).c_str(), &display.draws_faces) &&
      !display.draws_faces)
    display.draws_wireframe = true;
  if (ImGui::MenuItem("Wireframe overlay", nullptr, &is_wire)) display.draws_wireframe = is_wire;
  if (ImGui::BeginMenu("Shading")) {
    if (ImGui::MenuItem("Automatic: flat until subdivided", nullptr,
                        display.shading == render::Shading::automatic))
      display.shading = render::Shading::automatic;
    if (ImGui::MenuItem("Smooth", nullptr, display.shading == render::Shading::smooth))
      display.shading = render::Shading::smooth;
    if (ImGui::MenuItem("Flat", nullptr, display.shading == render::Shading::flat))
      display.shading = render::Shading::flat;
    ImGui::TextDisabled("%s cycles them", shortcut(Action::toggle_shading).c_str());
    ImGui::EndMenu();
  }
  bool is_culled = display.back_faces == render::BackFacePolicy::cull;
  if (ImGui::MenuItem("Back-face culling", shortcut(Action::toggle_culling).c_str(), &is_culled))
    display.back_faces = is_culled ? render::BackFacePolicy::cull : render::BackFacePolicy::different;
  bool is_back_colored = display.back_faces == render::BackFacePolicy::different;
  if (ImGui::MenuItem("Back faces in their own colour", nullptr, &is_back_colored))
    display.back_faces = is_back_colored ? render::BackFacePolicy::different : render::BackFacePolicy::same;
  ImGui::MenuItem("Möbius edges", nullptr, &display.draws_mobius_edges);
  ImGui::MenuItem("Borders", nullptr, &display.draws_borders);
  ImGui::MenuItem("Instance colours", nullptr, &display.uses_face_colors);
  ImGui::MenuItem("The scene's lights", nullptr, &display.uses_scene_lights);
  if (ImGui::BeginMenu("Palette")) {
    const render::DisplaySettings plain;
    if (ImGui::MenuItem("Nome: gold front, blue back")) {
      display.front_color = plain.front_color;
      display.back_color = plain.back_color;
      display.back_faces = render::BackFacePolicy::different;
    }
    if (ImGui::MenuItem("JIPCAD: orange front, dark grey back")) render::use_jipcad_palette(display);
    ImGui::EndMenu();
  }
  ImGui::Separator();
  action_item(actions, "Frame all", Action::frame_all);
  action_item(actions, "Section plane", Action::toggle_section);
  action_item(actions, "Reset view", Action::reset_view);
  action_item(actions, "Turntable", Action::toggle_turntable);
  action_item(actions, "Front", Action::view_front);
  action_item(actions, "Right", Action::view_right);
  action_item(actions, "Top", Action::view_top);
  ImGui::Separator();
  ImGui::MenuItem("Controls sidebar", nullptr, &layout.is_left_shown);
  ImGui::MenuItem("Parameters sidebar", nullptr, &layout.is_right_shown);
  action_item(actions, "Hide / show both sidebars", Action::toggle_sidebars);
  ImGui::MenuItem("Log open", shortcut(Action::toggle_log).c_str(), &layout.is_log_open);
  ImGui::MenuItem("Scene text", shortcut(Action::toggle_text_pane).c_str(), &layout.is_pane_shown);
  ImGui::MenuItem("Dark theme", nullptr, &layout.is_dark);
}

}  // namespace

std::optional<std::filesystem::path> draw_main_menu(const ActionRegistry& actions, const MenuContext& context,
                                                    render::DisplaySettings& display,
                                                    LayoutSettings& layout) {
  if (!ImGui::BeginMainMenuBar()) return std::nullopt;
  std::optional<std::filesystem::path> chosen;
  if (ImGui::BeginMenu("File")) {
    chosen = draw_file_menu(actions, context);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    action_item(actions, "Undo", Action::undo, context.can_undo);
    action_item(actions, "Redo", Action::redo, context.can_redo);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    draw_view_menu(actions, display, layout);
    ImGui::EndMenu();
  }
  // Commands the tools add beyond the action table: reachable without their keys.
  if (!actions.tool_commands().empty() && ImGui::BeginMenu("Tools")) {
    for (const ToolCommandInfo& command : actions.tool_commands()) {
      const std::string key = command.key != 0 ? key_label(command.key, command.modifiers) : std::string();
      if (ImGui::MenuItem(command.description.c_str(), key.c_str())) actions.run_tool_command(command.name);
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    action_item(actions, "Keys and mouse", Action::toggle_help);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
  return chosen;
}

}  // namespace nome::viewer

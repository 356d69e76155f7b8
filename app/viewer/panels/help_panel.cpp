#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {
namespace {

void draw_row(const char* what, const char* does) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(what);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(does);
}

}  // namespace

void draw_help_overlay(const ActionRegistry& actions, bool& is_shown) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  if (!ImGui::Begin("Keys and mouse (? or F1 closes)", &is_shown,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    draw_row("left drag", "turn (arcball)");
    draw_row("right / middle drag", "pan");
    draw_row("wheel", "zoom");
    draw_row("left click", "select in the current mode (again: deselect)");
    draw_row("right click", "clear the selection");
    draw_row("double click", "orbit around the point clicked");
    for (const ActionInfo& row : action_table())
      if (row.key != 0) draw_row(key_label(row.key, row.modifiers).c_str(), row.description);
    for (const ToolCommandInfo& row : actions.tool_commands())
      if (row.key != 0) draw_row(key_label(row.key, row.modifiers).c_str(), row.description.c_str());
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace nome::viewer

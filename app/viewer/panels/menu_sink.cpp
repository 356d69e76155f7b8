#include "viewer/panels/menu_sink.hpp"

#include <imgui.h>

namespace nome::viewer {

bool ImGuiMenuSink::begin_bar() {
  return ImGui::BeginMainMenuBar();
}

void ImGuiMenuSink::end_bar() {
  ImGui::EndMainMenuBar();
}

bool ImGuiMenuSink::begin_menu(const char* label, bool is_enabled) {
  return ImGui::BeginMenu(label, is_enabled);
}

void ImGuiMenuSink::end_menu() {
  ImGui::EndMenu();
}

bool ImGuiMenuSink::item(const char* label, const std::string& shortcut, bool is_checked, bool is_enabled) {
  return ImGui::MenuItem(label, shortcut.empty() ? nullptr : shortcut.c_str(), is_checked, is_enabled);
}

void ImGuiMenuSink::separator() {
  ImGui::Separator();
}

void ImGuiMenuSink::note(const std::string& text) {
  ImGui::TextDisabled("%s", text.c_str());
}

}  // namespace nome::viewer

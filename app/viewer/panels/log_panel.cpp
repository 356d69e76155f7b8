#include <algorithm>

#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {
namespace {

std::optional<scene::SourcePlace> draw_messages(const MessageLog& log, double scroll) {
  std::optional<scene::SourcePlace> clicked;
  for (const Message& m : log.messages()) {
    const bool is_colored = m.level != MessageLevel::info;
    if (is_colored) ImGui::PushStyleColor(ImGuiCol_Text, message_color(m.level));
    const char* prefix = m.level == MessageLevel::error     ? "error: "
                         : m.level == MessageLevel::warning ? "warning: "
                                                            : "";
    if (m.count > 1)
      ImGui::TextWrapped("%s%s (x%zu)", prefix, m.text.c_str(), m.count);
    else
      ImGui::TextWrapped("%s%s", prefix, m.text.c_str());
    if (is_colored) ImGui::PopStyleColor();
    if (m.place && ImGui::IsItemHovered()) {
      ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
      ImGui::SetTooltip("click: line %d, column %d in the text pane", m.place->location.line,
                        m.place->location.column);
    }
    if (m.place && ImGui::IsItemClicked()) clicked = m.place;
  }
  if (scroll != 0.0)
    ImGui::SetScrollY(ImGui::GetScrollY() + float(scroll));
  else if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY())
    ImGui::SetScrollHereY(1.0f);
  return clicked;
}

}  // namespace

std::optional<scene::SourcePlace> draw_log_panel(const MessageLog& log, const ScreenRect& rect, bool& is_open,
                                                 double scroll) {
  std::optional<scene::SourcePlace> clicked;
  ImGui::SetNextWindowPos(ImVec2(float(rect.origin.x), float(rect.origin.y)));
  ImGui::SetNextWindowSize(ImVec2(float(rect.size.x), float(rect.size.y)));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::Begin("Log", nullptr, flags);
  if (ImGui::ArrowButton("##open", is_open ? ImGuiDir_Down : ImGuiDir_Right)) is_open = !is_open;
  ImGui::SameLine();
  ImGui::Text("Log (%zu)", log.messages().size());
  if (is_open) {
    ImGui::BeginChild("messages");
    clicked = draw_messages(log, scroll);
    ImGui::EndChild();
  }
  ImGui::End();
  return clicked;
}

}  // namespace nome::viewer

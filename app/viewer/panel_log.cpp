#include <algorithm>

#include <imgui.h>

#include "viewer/panels.hpp"

namespace nome::viewer {

void draw_log_panel(const MessageLog& log, bool& is_shown) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float height = 130.0f;
  ImGui::SetNextWindowPos(ImVec2(8, size.y - status_bar_height() - height - 6), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::min(size.x - 16, 760.0f), height), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Log", &is_shown)) {
    ImGui::End();
    return;
  }
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
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
  ImGui::End();
}

}  // namespace nome::viewer

#include <cstdio>

#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {

ImVec4 message_color(MessageLevel level) {
  return level == MessageLevel::error ? ImVec4(0.85f, 0.15f, 0.15f, 1.0f) : ImVec4(0.80f, 0.55f, 0.05f, 1.0f);
}

std::string size_text(const glm::dvec3& size) {
  char text[96];
  std::snprintf(text, sizeof text, "%.4g x %.4g x %.4g mm", size.x, size.y, size.z);
  return text;
}

float status_bar_height() {
  return ImGui::GetFrameHeight() + 4.0f;
}

void draw_status_bar(const std::optional<StatusLine>& status, const MessageLog& log) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, size.y - status_bar_height()));
  ImGui::SetNextWindowSize(ImVec2(size.x, status_bar_height()));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::Begin("##status", nullptr, flags);
  if (status) {
    ImGui::Text("%s%s | %s stage: %u V, %u F, %s", status->file.c_str(), status->is_modified ? " *" : "",
                to_string(status->stage), status->vertices, status->faces, size_text(status->size).c_str());
    for (const std::string& note : status->notes) {
      ImGui::SameLine();
      ImGui::Text("| %s", note.c_str());
    }
  } else {
    ImGui::TextUnformatted("no file: File > Open (Ctrl+O) or drop a file on the window");
  }
  if (const Message* latest = log.latest()) {
    ImGui::SameLine();
    ImGui::TextUnformatted("|");
    ImGui::SameLine();
    if (latest->level == MessageLevel::info)
      ImGui::TextUnformatted(latest->text.c_str());
    else
      ImGui::TextColored(message_color(latest->level), "%s", latest->text.c_str());
  }
  ImGui::End();
}

}  // namespace nome::viewer

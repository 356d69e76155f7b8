#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {

void draw_progress(double seconds_running, const WorkProgress& progress) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, 40.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##progress", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const char* spinner = "|/-\\";
  const char spin = spinner[int(seconds_running * 8.0) % 4];
  if (progress.task.empty())
    ImGui::Text("%c computing the stage ... %.1f s", spin, seconds_running);
  else
    ImGui::Text("%c computing the stage: %s %d%% ... %.1f s", spin, progress.task.c_str(),
                int(progress.fraction * 100.0), seconds_running);
  ImGui::End();
}

}  // namespace nome::viewer

#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {

bool begin_docked_panel(const char* title, const ScreenRect& rect, double* width, double scroll) {
  // Placed every frame: the layout owns the place. ImGui applies a drag of the edge after this size,
  // so the dragged width is read back below and becomes the layout's for the next frame.
  ImGui::SetNextWindowPos(ImVec2(float(rect.origin.x), float(rect.origin.y)));
  ImGui::SetNextWindowSize(ImVec2(float(rect.size.x), float(rect.size.y)));
  ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (!width) flags |= ImGuiWindowFlags_NoResize;
  const bool is_open = ImGui::Begin(title, nullptr, flags);
  if (width) *width = ImGui::GetWindowWidth();
  if (scroll != 0.0) ImGui::SetScrollY(ImGui::GetScrollY() + float(scroll));
  return is_open;
}

}  // namespace nome::viewer

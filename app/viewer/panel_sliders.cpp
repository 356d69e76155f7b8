#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "viewer/panels.hpp"

namespace nome::viewer {

std::optional<std::pair<Index, double>> draw_slider_panels(const scene::Scene& scene) {
  std::optional<std::pair<Index, double>> moved;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  float y = 206.0f;  // below the topology panel
  for (const scene::Bank& bank : scene.banks()) {
    ImGui::SetNextWindowPos(ImVec2(size.x - 338, y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
    y += 40.0f + 26.0f * float(bank.parameters.size());
    if (!ImGui::Begin(("bank " + bank.name).c_str())) {
      ImGui::End();
      continue;
    }
    for (Index id : bank.parameters) {
      const scene::Parameter& p = scene.parameters()[id];
      float value = float(p.value);
      ImGui::SetNextItemWidth(-70);
      // Ctrl+click on a slider types an exact value (ImGui's own behaviour).
      if (ImGui::SliderFloat(p.name.c_str(), &value, float(p.min), float(p.max), "%.4g")) {
        double snapped = value;
        if (p.step > 0.0) snapped = p.min + std::round((value - p.min) / p.step) * p.step;
        snapped = std::clamp(snapped, p.min, p.max);
        if (snapped != p.value) moved = {id, snapped};
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("$%s: %g .. %g, step %g", p.full_name.c_str(), p.min, p.max, p.step);
    }
    ImGui::End();
  }
  return moved;
}

}  // namespace nome::viewer

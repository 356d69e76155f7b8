#include <imgui.h>

#include "viewer/panels.hpp"

namespace nome::viewer {
namespace {

void draw_component_row(std::size_t i, const ComponentTopology& c) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::Text("%zu", i);
  ImGui::TableNextColumn();
  ImGui::Text("%u", c.vertices);
  ImGui::TableNextColumn();
  ImGui::Text("%u", c.edges);
  ImGui::TableNextColumn();
  ImGui::Text("%u", c.faces);
  ImGui::TableNextColumn();
  ImGui::Text("%lld", c.chi);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(c.orientable ? "yes" : "no");
  ImGui::TableNextColumn();
  ImGui::Text("%u", c.borders);
  ImGui::TableNextColumn();
  ImGui::Text("%lld", c.genus);
}

}  // namespace

void draw_topology_panel(const TopologyReport& report) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x - 338, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 170), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Topology")) {
    ImGui::End();
    return;
  }
  ImGui::Text("V %u  E %u  F %u  chi %lld", report.vertices, report.edges, report.faces, report.chi);
  ImGui::Text("%s, %u borders, %u Möbius edges", report.orientable ? "orientable" : "non-orientable",
              report.borders, report.mobius_edges);
  constexpr std::size_t shown_rows = 64;
  if (ImGui::BeginTable("components", 8, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* title : {"#", "V", "E", "F", "chi", "or.", "b", "g"}) ImGui::TableSetupColumn(title);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < report.components.size() && i < shown_rows; ++i)
      draw_component_row(i, report.components[i]);
    ImGui::EndTable();
  }
  if (report.components.size() > shown_rows)
    ImGui::Text("... %zu components in all", report.components.size());
  ImGui::End();
}

}  // namespace nome::viewer

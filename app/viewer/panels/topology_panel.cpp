#include <imgui.h>

#include "viewer/panels/panels.hpp"

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

void draw_topology_section(const TopologyReport& report, const glm::dvec3& size) {
  ImGui::Text("size %s", size_text(size).c_str());
  ImGui::Text("V %u  E %u  F %u  chi %lld", report.vertices, report.edges, report.faces, report.chi);
  ImGui::TextWrapped("%s, %u borders, %u Möbius edges", report.orientable ? "orientable" : "non-orientable",
                     report.borders, report.mobius_edges);
  constexpr std::size_t shown_rows = 64;
  // Many parts make a long table: a line that opens it.
  constexpr std::size_t parts_in_a_line = 4;
  if (report.components.size() > parts_in_a_line &&
      !ImGui::TreeNode("parts", "%zu parts (table)", report.components.size()))
    return;
  const bool is_tree_open = report.components.size() > parts_in_a_line;
  if (ImGui::BeginTable("components", 8, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* title : {"#", "V", "E", "F", "chi", "or.", "b", "g"}) ImGui::TableSetupColumn(title);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < report.components.size() && i < shown_rows; ++i)
      draw_component_row(i, report.components[i]);
    ImGui::EndTable();
  }
  if (report.components.size() > shown_rows)
    ImGui::Text("... %zu components in all", report.components.size());
  if (is_tree_open) ImGui::TreePop();
}

}  // namespace nome::viewer

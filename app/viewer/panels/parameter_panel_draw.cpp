#include <algorithm>
#include <optional>
#include <string>

#include <imgui.h>

#include "viewer/panels/parameter_panel.hpp"

namespace nome::viewer {
namespace {

// Tints the frame of a slider moved from its file value.
const ImVec4 moved_color(0.95f, 0.75f, 0.30f, 0.55f);

void draw_slider_menu(const scene::Parameter& p, scene::ParameterId id, ParameterPanelState& state,
                      std::optional<double>& moved) {
  if (!ImGui::BeginPopupContextItem("slider menu")) return;
  const auto range = state.range(p, id);
  if (ImGui::IsWindowAppearing()) {
    state.typed_value = p.value;
    state.typed_range = {range.first, range.second};
  }
  ImGui::TextDisabled("$%s", p.full_name.c_str());
  const double file_value = state.file_values.contains(id) ? state.file_values[id] : p.value;
  const std::string reset = "Reset to the file's value (" + std::to_string(file_value) + ")";
  if (ImGui::MenuItem(reset.c_str())) moved = file_value;
  ImGui::SetNextItemWidth(160);
  if (ImGui::InputDouble("value", &state.typed_value, 0.0, 0.0, "%.6g",
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
    // As a value typed with Ctrl+click: on the slider's step, within its range.
    moved = snap_to_step(p, state.typed_value, range);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SetNextItemWidth(160);
  // The kernel refuses values outside the file's range, so a session's range lies within it.
  if (ImGui::InputScalarN("range", ImGuiDataType_Double, state.typed_range.data(), 2, nullptr, nullptr,
                          "%.6g", ImGuiInputTextFlags_EnterReturnsTrue)) {
    const double low = std::max(p.min, state.typed_range[0]);
    const double high = std::min(p.max, state.typed_range[1]);
    if (low < high) state.ranges[id] = {low, high};
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("for this session, within the file's %g .. %g", p.min, p.max);
  if (ImGui::MenuItem("File's range", nullptr, false, state.ranges.count(id) > 0)) state.ranges.erase(id);
  ImGui::EndPopup();
}

// One slider row; returns the value the user moved it to. `continues`: by a drag begun earlier.
std::optional<double> draw_slider(const scene::Parameter& p, scene::ParameterId id,
                                  ParameterPanelState& state, bool& continues) {
  ImGui::PushID(int(id.index()));
  std::optional<double> moved;
  const bool is_moved = state.is_moved(p, id);
  const auto range = state.range(p, id);
  ImGui::TextUnformatted(is_moved ? "*" : " ");
  ImGui::SameLine();
  if (is_moved) ImGui::PushStyleColor(ImGuiCol_FrameBg, moved_color);
  // A double from the panel to the kernel: a slider's steps (0.1) and its file value stay exact.
  double value = p.value;
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 6.0f);
  // Ctrl+click types an exact value (ImGui's own behaviour).
  // A SLIDE scale's label where it has one; its name keeps the row's id.
  const std::string text = p.label.empty() ? p.name : p.label + "##" + p.name;
  if (ImGui::SliderScalar(text.c_str(), ImGuiDataType_Double, &value, &range.first, &range.second, "%.4g"))
    moved = snap_to_step(p, value, range);
  continues = ImGui::IsItemActive() && !ImGui::IsItemActivated();
  if (is_moved) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("$%s: %g .. %g, step %g%s", p.full_name.c_str(), p.min, p.max, p.step,
                      is_moved ? " (moved: right-click to reset)" : "");
    const double step = p.step > 0.0 ? p.step : (range.second - range.first) / 100.0;
    const int direction = int(ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) -
                          int(ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)));
    if (direction != 0) moved = snap_to_step(p, p.value + direction * step, range);
  }
  draw_slider_menu(p, id, state, moved);
  ImGui::PopID();
  if (moved && *moved == p.value) moved.reset();
  return moved;
}

// The header's rectangle when all of it is in the panel's visible part.
void report_header(const std::string& name, LayoutReport& report) {
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const ImVec2 one(1.0f, 1.0f);
  if (!ImGui::IsRectVisible(min, ImVec2(min.x + one.x, min.y + one.y)) ||
      !ImGui::IsRectVisible(ImVec2(max.x - one.x, max.y - one.y), max))
    return;
  report.banks.push_back({name, {{min.x, min.y}, {max.x - min.x, max.y - min.y}}});
}

void draw_bank(const scene::Scene& scene, const scene::Bank& bank,
               const std::vector<scene::ParameterId>& shown, bool is_selected, ParameterPanelState& state,
               LayoutReport& report, ParameterMoves& moves) {
  std::size_t moved_count = 0;
  for (scene::ParameterId id : bank.parameters) moved_count += state.is_moved(scene.parameters()[id], id);
  std::string label = bank.name;
  if (is_selected) label += "  (selection)";
  if (moved_count > 0) label += "  (" + std::to_string(moved_count) + " moved)";
  label += "###" + bank.name;
  const bool is_open = ImGui::CollapsingHeader(label.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
  report_header(bank.name, report);
  if (!is_open) return;
  ImGui::PushID(bank.name.c_str());
  for (scene::ParameterId id : shown) {
    bool continues = false;
    if (const auto value = draw_slider(scene.parameters()[id], id, state, continues)) {
      moves.moves.push_back({id, *value});
      moves.continues = continues;
    }
  }
  ImGui::BeginDisabled(moved_count == 0);
  if (ImGui::SmallButton("reset bank"))
    for (const auto& move : bank_reset(scene, bank, state)) moves.moves.push_back(move);
  ImGui::EndDisabled();
  ImGui::PopID();
}

}  // namespace

ParameterMoves draw_parameter_section(const scene::Scene& scene,
                                      const std::vector<scene::ParameterId>& selected,
                                      ParameterPanelState& state, LayoutReport& report) {
  ParameterMoves moves;
  state.track(scene);
  if (scene.banks().empty()) {
    ImGui::TextDisabled("no sliders in this scene");
    return moves;
  }
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##filter", "filter: part of a slider's name", state.filter.data(),
                           state.filter.size());
  const std::string filter = state.filter.data();
  bool is_any_shown = false;
  const std::vector<Index> order = bank_order(scene, selected);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const scene::Bank& bank = scene.banks()[order[i]];
    const std::vector<scene::ParameterId> shown = filtered_parameters(scene, bank, filter);
    if (shown.empty()) continue;
    is_any_shown = true;
    draw_bank(scene, bank, shown, holds_any(bank, selected), state, report, moves);
  }
  if (!is_any_shown) ImGui::TextDisabled("no slider matches '%s'", filter.c_str());
  return moves;
}

}  // namespace nome::viewer

#include "viewer/tools/selection_tool.hpp"

#include <algorithm>

#include <imgui.h>

#include "viewer/view/picking.hpp"

namespace nome::viewer {
namespace {

SelectionMode mode_named(const std::string& word) {
  if (word == "face") return SelectionMode::face;
  if (word == "border") return SelectionMode::border;
  if (word == "border-partial") return SelectionMode::border_partial;
  if (word == "edge") return SelectionMode::edge;
  if (word == "instance") return SelectionMode::instance;
  return SelectionMode::vertex;
}

// The selected edges' crease weights on the shown mesh: one, or their range.
void draw_selected_sharpness(const Selection& selection, const Mesh* shown) {
  if (!shown || selection.edges().empty()) return;
  float low = infinite_sharpness, high = 0.0f;
  for (Index e : selection.edges()) {
    low = std::min(low, shown->edge_sharpness(e));
    high = std::max(high, shown->edge_sharpness(e));
  }
  const std::string text =
      low == high ? sharpness_text(low) : sharpness_text(low) + " to " + sharpness_text(high);
  ImGui::Text("sharpness: %s", text.c_str());
}

bool draw_selection_section(const ActionRegistry& actions, Selection& selection, glm::vec3& instance_color,
                            const Mesh* shown) {
  int mode = int(selection.mode());
  const char* labels[] = {"vertex", "face", "border", "part of border", "edge", "instance"};
  for (int i = 0; i < 6; ++i) {
    if (ImGui::RadioButton(labels[i], &mode, i)) selection.set_mode(SelectionMode(i));
    if (i % 2 == 0) ImGui::SameLine(ImGui::GetFontSize() * 8.0f);
  }
  ImGui::NewLine();
  ImGui::TextWrapped("%zu vertices, %zu faces, %zu edges, %zu borders", selection.vertices().size(),
                     selection.faces().size(), selection.edges().size(), selection.borders().size());
  draw_selected_sharpness(selection, shown);
  if (ImGui::Button("Clear selection")) actions.run(Action::clear_selection);
  if (selection.mode() != SelectionMode::instance) return false;
  // Report 8.4: selected instances take a surface colour, saved with the scene.
  ImGui::Text("%zu instances selected", selection.instances().size());
  ImGui::ColorEdit3("instance colour", &instance_color.x, ImGuiColorEditFlags_NoInputs);
  ImGui::SameLine();
  ImGui::BeginDisabled(selection.instances().empty());
  const bool is_applied = ImGui::Button("Colour selected");
  ImGui::EndDisabled();
  return is_applied;
}

}  // namespace

void SelectionTool::draw_section(ToolContext& context) {
  if (draw_selection_section(context.actions, context.selection, instance_color_, context.stage.shown_mesh()))
    color_instances(context, instance_color_);
}

bool SelectionTool::click(ToolContext& context, glm::dvec2 pixel) {
  const StageResult* shown = context.stage.shown();
  if (!shown) return false;
  const ScreenProjection projection = context.view.projection(context.layout.viewport);
  Selection& selection = context.selection;
  const std::string hint =
      selection.mode() == SelectionMode::instance
          ? select_instance(selection, *shown, context.stage.picking_bvh(), context.sessions.session(),
                            projection, pixel)
          : select_at(selection, *shown, context.stage.picking_bvh(), context.rims, projection, pixel);
  if (!hint.empty()) context.log.info(hint);
  context.refresh_selection();
  return true;
}

std::optional<bool> SelectionTool::run_script(ToolContext& context, const ScriptCommand& command) {
  using Kind = ScriptCommand::Kind;
  if (command.kind == Kind::mode) {
    context.selection.set_mode(mode_named(command.words[0]));
    return true;
  }
  if (command.kind != Kind::color) return std::nullopt;
  return color_instances(context, glm::vec3(command.numbers[0], command.numbers[1], command.numbers[2]));
}

std::string SelectionTool::status_text(const ToolContext& context) const {
  const Selection& selection = context.selection;
  std::string text = std::string(to_string(selection.mode())) + " mode";
  if (selection.instances().empty()) return text;
  text += " | instances ";
  for (std::size_t i = 0; i < selection.instances().size(); ++i)
    text += (i == 0 ? "" : ", ") + selection.instances()[i];
  return text;
}

bool SelectionTool::color_instances(ToolContext& context, glm::vec3 color) {
  instance_color_ = color;
  if (!context.sessions.color_instances(context.selection.instances(), color)) return false;
  context.refresh_selection();
  return true;
}

}  // namespace nome::viewer

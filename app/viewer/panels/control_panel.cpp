#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <imgui.h>

#include "viewer/panels/panels.hpp"

namespace nome::viewer {
namespace {

// The next item takes this part of the width left on its line: the sidebar may be narrow.
void set_width_part(float part) {
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * part);
}

// The crease method and the smooth-triangle rule (OpenSubdiv's `t creasemethod`, `t smoothtriangles`).
void draw_crease_controls(CreaseOptions& creases) {
  int method = int(creases.method);
  const char* methods[] = {to_string(CreaseMethod::uniform), to_string(CreaseMethod::chaikin)};
  set_width_part(0.5f);
  if (ImGui::Combo("creases", &method, methods, IM_ARRAYSIZE(methods))) creases.method = CreaseMethod(method);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "how semi-sharp weights decay: uniform (1 per level) or Chaikin (evened out along a crease)");
  ImGui::Checkbox("smooth triangles", &creases.smooth_triangles);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("OpenSubdiv's smooth triangle rule: edge points beside a triangle lean to its centre");
}

void draw_stage_section(const ActionRegistry& actions, PipelineSettings& settings) {
  const std::span<const Stage> order = builtin_stage_order();
  std::vector<const char*> names;
  for (Stage stage : order) names.push_back(to_string(stage));
  int shown = int(std::find(order.begin(), order.end(), settings.stage) - order.begin());
  set_width_part(0.7f);
  if (ImGui::Combo("show", &shown, names.data(), int(names.size()))) settings.stage = order[size_t(shown)];
  if (ImGui::Button("Merge")) actions.run(Action::merge);
  ImGui::SameLine();
  float tolerance = float(settings.merge_tolerance);
  set_width_part(0.5f);
  if (ImGui::InputFloat("tolerance", &tolerance, 0.0f, 0.0f, "%.5f", ImGuiInputTextFlags_EnterReturnsTrue))
    settings.merge_tolerance = std::max(0.0f, tolerance);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("0: a thousandth of the scene's size");
  ImGui::Checkbox("subdivide the merged mesh", &settings.should_merge);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("off: the scene's pieces are subdivided each on its own");
  set_width_part(0.4f);
  ImGui::SliderInt("subdivision", &settings.subdivision_levels, 0, 6);
  int rule = int(settings.rule);
  const char* rules[] = {"classic", "report"};
  set_width_part(0.5f);
  if (ImGui::Combo("rule", &rule, rules, IM_ARRAYSIZE(rules))) settings.rule = SubdivisionRule(rule);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("smooth-vertex rule: Catmull-Clark's or the 2016 report's");
  int boundary = int(settings.boundary);
  const char* boundaries[] = {to_string(BoundaryMode::none), to_string(BoundaryMode::edge_only),
                              to_string(BoundaryMode::edge_and_corner)};
  set_width_part(0.7f);
  if (ImGui::Combo("border", &boundary, boundaries, IM_ARRAYSIZE(boundaries)))
    settings.boundary = BoundaryMode(boundary);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "edge-only: a vertex of one face follows the border; edge-and-corner: it stays put;\n"
        "none: faces touching the border shape their neighbours but are not shown");
  draw_crease_controls(settings.creases);
  float distance = float(settings.offset_distance);
  set_width_part(0.5f);
  if (ImGui::SliderFloat("offset", &distance, 0.001f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic))
    settings.offset_distance = std::max(distance, 1e-6f);
  set_width_part(0.35f);
  ImGui::SliderInt("levels after offset", &settings.subdivision_after, 0, 4);
}

// The marker of edits a slider left without their vertices: kept, hidden, back when the slider returns.
void draw_unresolved(const std::vector<UnresolvedEdit>& unresolved) {
  if (unresolved.empty()) return;
  ImGui::TextColored(message_color(MessageLevel::warning), "(!) %zu edits unresolved (hidden, kept)",
                     unresolved.size());
  if (!ImGui::IsItemHovered()) return;
  std::string text = "their vertices are gone at these slider values; they come back with them:";
  for (const UnresolvedEdit& edit : unresolved) {
    text += "\n  " + edit.face + ": ";
    if (edit.missing.empty()) text += "its face is gone";
    for (const std::string& v : edit.missing) text += v + " ";
  }
  ImGui::SetTooltip("%s", text.c_str());
}

// The weight K gives: OpenSubdiv's sharpness, a crease for that many levels (fractions blend), or infinite.
void draw_sharpness_control(float& sharpness) {
  bool is_infinite = sharpness >= infinite_sharpness;
  if (ImGui::Checkbox("infinite", &is_infinite)) sharpness = is_infinite ? infinite_sharpness : 2.0f;
  ImGui::SameLine();
  ImGui::BeginDisabled(is_infinite);
  float weight = std::min(sharpness, infinite_sharpness);
  set_width_part(0.45f);
  if (ImGui::SliderFloat("sharpness", &weight, 0.0f, infinite_sharpness, "%.2f")) sharpness = weight;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("the edges stay creased for this many subdivision levels (fractions blend)");
}

void draw_edit_section(const ActionRegistry& actions, const ControlPanelModel& model) {
  if (!is_editable(model.settings.stage)) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s is computed: edit on scene or merged", to_string(model.settings.stage));
    ImGui::PopTextWrapPos();
  }
  ImGui::BeginDisabled(!model.can_edit);
  if (ImGui::Button("Add polygon")) actions.run(Action::add_polygon);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("through the selected vertices, in click order (Enter)");
  ImGui::SameLine();
  if (ImGui::Button("Delete faces")) actions.run(Action::delete_faces);
  if (ImGui::Button("Sharp / smooth")) actions.run(Action::toggle_sharp);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("give the selected edges the sharpness, or smooth them if all have it (K)");
  ImGui::SameLine();
  if (ImGui::Button("Zip borders")) actions.run(Action::zip);
  float penalty = float(model.zipper.triangle_penalty);
  set_width_part(0.45f);
  if (ImGui::SliderFloat("triangle penalty", &penalty, 1.0f, 3.0f, "%.2f"))
    model.zipper.triangle_penalty = penalty;
  draw_sharpness_control(model.sharpness);
  ImGui::EndDisabled();
  ImGui::BeginDisabled(!model.document || model.document->temporary_faces().empty());
  if (ImGui::Button("Accept")) actions.run(Action::accept);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("move the temporary faces into the consolidated mesh");
  ImGui::SameLine();
  if (ImGui::Button("Clear temporary")) actions.run(Action::clear_temporary);
  ImGui::EndDisabled();
  if (const Document* document = model.document) {
    ImGui::TextWrapped("%zu temporary, %zu consolidated, %zu deleted", document->temporary_faces().size(),
                       document->consolidated_faces().size(), document->deleted_faces().size());
    draw_unresolved(document->unresolved());
  }
  bool is_locked = model.is_parameter_lock_on;
  if (ImGui::Checkbox("lock sliders while editing", &is_locked)) actions.run(Action::toggle_parameter_lock);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("on: the sliders do not move while there are edits, so none can lose its vertices");
}

ControlPanelChanges draw_color_section(const ControlPanelModel& model) {
  const ImGuiColorEditFlags flags = ImGuiColorEditFlags_NoInputs;
  render::DisplaySettings& display = model.display;
  ControlPanelChanges changes;
  ImGui::ColorEdit3("default", &display.front_color.x, flags);
  ImGui::ColorEdit3("back faces", &display.back_color.x, flags);
  changes.is_selection_changed = ImGui::ColorEdit3("selected", &display.selection_color.x, flags);
  ImGui::ColorEdit3("background", &display.background.x, flags);
  ImGui::ColorEdit3("rim lines", &model.display.rim_color.x, flags);
  changes.is_edit_color_changed = ImGui::ColorEdit3("temporary", &model.edit_colors.temporary.x, flags);
  changes.is_edit_color_changed |=
      ImGui::ColorEdit3("consolidated", &model.edit_colors.consolidated.x, flags);
  return changes;
}

}  // namespace

ControlPanelChanges draw_control_panel(const ActionRegistry& actions, ControlPanelModel model) {
  ControlPanelChanges changes;
  if (ImGui::CollapsingHeader("Stage", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (model.sif_pairing) {
      bool is_paired = *model.sif_pairing;
      if (ImGui::Checkbox("pair triangles into quads (.sif)", &is_paired))
        actions.run(Action::toggle_sif_pairing);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "report 7.1: convex, nearly planar pairs; fewer extraordinary points when subdividing");
    }
    draw_stage_section(actions, model.settings);
  }
  if (ImGui::CollapsingHeader("Edit", ImGuiTreeNodeFlags_DefaultOpen)) draw_edit_section(actions, model);
  if (ImGui::CollapsingHeader("Colours")) changes = draw_color_section(model);
  return changes;
}

}  // namespace nome::viewer

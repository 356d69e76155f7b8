#include "viewer/tools/section_tool.hpp"

#include <algorithm>

#include <imgui.h>

#include <glm/geometric.hpp>

namespace nome::viewer {
namespace {

glm::dvec3 section_normal(const SectionState& state, const render::Camera& camera) {
  if (state.orientation == SectionState::Orientation::view)
    return camera.orientation * glm::dvec3(0.0, 0.0, 1.0);  // towards the eye: the near half goes
  glm::dvec3 n(0.0);
  n[int(state.orientation)] = 1.0;
  return n;
}

}  // namespace

void draw_section_panel(SectionState& state, const glm::dvec3& low, const glm::dvec3& high) {
  ImGui::Checkbox("cut (C)", &state.is_on);
  int orientation = int(state.orientation);
  if (ImGui::Combo("normal", &orientation, "x\0y\0z\0view direction\0\0")) {
    state.orientation = SectionState::Orientation(orientation);
    state.offset = 0.0;
  }
  const double half = 0.5 * std::max(glm::length(high - low), 1e-9);
  const double extent = state.orientation == SectionState::Orientation::view
                            ? half
                            : 0.5 * (high - low)[int(state.orientation)] + 1e-9;
  double offset = state.offset;
  const double lowest = -extent, highest = extent;
  if (ImGui::SliderScalar("position", ImGuiDataType_Double, &offset, &lowest, &highest, "%.4g"))
    state.offset = offset;
  ImGui::TextDisabled("a solid's cut is filled red");
}

void apply_section(const SectionState& state, const render::Camera& camera, const glm::dvec3& centre,
                   bool is_solid, render::DisplaySettings& display) {
  display.section_plane = glm::vec4(0.0f);
  display.fills_section = false;
  if (!state.is_on) return;
  const glm::dvec3 n = section_normal(state, camera);
  const glm::dvec3 through =
      (state.orientation == SectionState::Orientation::view ? camera.target : centre) + state.offset * n;
  display.section_plane = glm::vec4(glm::vec3(n), float(-glm::dot(n, through)));
  display.fills_section = is_solid;
}

void SectionTool::bind(ToolContext& context) {
  context.actions.bind(Action::toggle_section, [this] { return state_.is_on = !state_.is_on, true; });
}

void SectionTool::before_draw(ToolContext& context) {
  const StageResult* shown = context.stage.shown();
  apply_section(state_, context.view.camera(), 0.5 * (context.shown_low + context.shown_high),
                shown && is_solid(shown->stage), context.display);
}

void SectionTool::draw_section(ToolContext& context) {
  draw_section_panel(state_, context.shown_low, context.shown_high);
}

}  // namespace nome::viewer

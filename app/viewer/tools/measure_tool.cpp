#include "viewer/tools/measure_tool.hpp"

#include <cstdio>

#include <imgui.h>

#include <glm/geometric.hpp>

#include "nome/query/wall_thickness.hpp"

namespace nome::viewer {

std::string measure_length_text(double length) {
  char text[48];
  std::snprintf(text, sizeof text, "%.4g mm", length);
  return text;
}

void MeasureTool::bind(ToolContext& context) {
  context.actions.bind(Action::measure_distance, [this] { return toggle(MeasureMode::distance), true; });
  context.actions.bind(Action::measure_wall, [this] { return toggle(MeasureMode::wall), true; });
}

bool MeasureTool::click(ToolContext& context, glm::dvec2 pixel) {
  const StageResult* shown = context.stage.shown();
  if (mode_ == MeasureMode::off || !shown) return false;
  const Ray ray = ray_through_pixel(context.view.projection(context.layout.viewport), pixel);
  context.log.info(click(*shown->mesh, context.stage.picking_bvh(), ray));
  return true;
}

void MeasureTool::draw_overlay(ToolContext& context) {
  draw_overlay(context.view.projection(context.layout.viewport));
}

void MeasureTool::toggle(MeasureMode mode) {
  mode_ = mode_ == mode ? MeasureMode::off : mode;
  first_.reset();
}

std::string MeasureTool::click(const Mesh& shown, const TriangleBvh& bvh, const Ray& ray) {
  const std::optional<RayHit> hit = bvh.cast_nearest(ray);
  if (!hit) return "measure: no surface under the cursor";
  if (mode_ == MeasureMode::wall) {
    const auto wall = wall_thickness(shown, bvh, hit->face, hit->point);
    if (!wall) return "measure: no wall here (the shown stage is not a closed solid: offset it)";
    last_ = Measurement{wall->from, wall->to, wall->thickness, true};
    return "wall " + measure_length_text(wall->thickness) + " at face " + std::to_string(hit->face);
  }
  if (!first_) {
    first_ = hit->point;
    return "measure: first point set, click the second";
  }
  last_ = Measurement{*first_, hit->point, glm::distance(*first_, hit->point), false};
  first_.reset();
  return "distance " + measure_length_text(last_->length);
}

void MeasureTool::draw_overlay(const ScreenProjection& projection) const {
  if (mode_ == MeasureMode::off) return;
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const ImU32 color = IM_COL32(230, 60, 30, 255);
  auto at = [&](const Vec3& p) -> std::optional<ImVec2> {
    const auto pixel = project_to_pixel(projection, p);
    if (!pixel) return std::nullopt;
    return ImVec2(float(pixel->x), float(pixel->y));
  };
  if (first_)
    if (const auto p = at(*first_)) list->AddCircleFilled(*p, 4.0f, color);
  if (!last_) return;
  const auto a = at(last_->from);
  const auto b = at(last_->to);
  if (!a || !b) return;
  list->AddLine(*a, *b, color, 2.0f);
  list->AddCircleFilled(*a, 3.0f, color);
  list->AddCircleFilled(*b, 3.0f, color);
  const std::string label = (last_->is_wall ? "wall " : "") + measure_length_text(last_->length);
  list->AddText(ImVec2(0.5f * (a->x + b->x) + 6.0f, 0.5f * (a->y + b->y)), color, label.c_str());
}

void MeasureTool::draw_section() {
  int mode = int(mode_);
  // Every button is drawn: no short-circuit.
  bool is_changed = ImGui::RadioButton("select", &mode, 0);
  is_changed |= ImGui::RadioButton("distance (M)", &mode, 1);
  is_changed |= ImGui::RadioButton("wall (Shift+M)", &mode, 2);
  if (is_changed && mode != int(mode_)) toggle(MeasureMode(mode));
  if (last_)
    ImGui::Text("%s %s", last_->is_wall ? "wall" : "distance", measure_length_text(last_->length).c_str());
  else
    ImGui::TextDisabled("click the surface to measure");
}

}  // namespace nome::viewer

#include "viewer/tools/print_check_tool.hpp"

#include <cstdio>

#include <imgui.h>

namespace nome::viewer {
namespace {

constexpr std::size_t listed_places = 24;

void draw_verdict(const PrintCheckRun& run, bool is_current) {
  const PrintCheck& check = run.check;
  const ImVec4 color =
      check.is_printable() ? ImVec4(0.1f, 0.6f, 0.25f, 1.0f) : ImVec4(0.85f, 0.1f, 0.1f, 1.0f);
  ImGui::TextColored(color, "%s", check.is_printable() ? "printable" : "not printable");
  ImGui::SameLine();
  ImGui::TextDisabled("(%.2f s%s)", run.seconds, is_current ? "" : ", out of date");
  ImGui::Text("offset %g, wall %g", check.offset_distance, check.min_wall);
  ImGui::Text("fold-over faces %zu", check.fold_over_faces.size());
  ImGui::Text("crossing faces %zu (%u curves)", check.crossings.faces.size(), check.crossings.curves);
  ImGui::Text("near-miss vertices %zu", check.near_misses.size());
}

// One selectable row per place, worst first; returns the clicked one.
std::optional<std::size_t> draw_places(const PrintCheck& check) {
  std::optional<std::size_t> clicked;
  char label[160];
  for (std::size_t i = 0; i < check.places.size() && i < listed_places; ++i) {
    const PrintPlace& p = check.places[i];
    if (p.kind == FindingKind::near_miss)
      std::snprintf(label, sizeof label, "%s  gap %.4g  (%u vertices)##place%zu", to_string(p.kind),
                    p.distance, p.size, i);
    else
      std::snprintf(label, sizeof label, "%s  face %u  (%u %s)##place%zu", to_string(p.kind), p.face, p.size,
                    p.kind == FindingKind::crossing ? "pairs" : "faces", i);
    if (ImGui::Selectable(label)) clicked = i;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("at (%.4g, %.4g, %.4g): click to frame it", p.position.x, p.position.y, p.position.z);
  }
  if (check.places.size() > listed_places) ImGui::TextDisabled("... %zu places in all", check.places.size());
  return clicked;
}

}  // namespace

void PrintCheckTool::bind(ToolContext& context) {
  context.actions.bind(Action::print_check, [this, &context] {
    const Session* session = context.sessions.session();
    if (!session) {
      context.log.warning("print check: open a scene or mesh first");
      return false;
    }
    job_.request(*session, context.stage.settings());
    return true;
  });
  context.actions.bind(Action::next_print_place, [this, &context] {
    if (!job_.last() || job_.last()->check.places.empty()) {
      context.log.warning("print check: no places to frame (run the check first)");
      return false;
    }
    const std::size_t place = job_.next_place();
    context.view.frame(job_.place_box(place), {}, context.layout.viewport);
    return true;
  });
}

void PrintCheckTool::update(ToolContext& context) {
  const Session* session = context.sessions.session();
  if (!session) return;
  try {
    if (!job_.update(context.stage, *session, context.platform.now())) return;
  } catch (const std::exception& e) {
    context.log.error("print check: " + std::string(e.what()));
    return;
  }
  const PrintCheck& check = job_.last()->check;
  context.log.info("print check: " + std::string(check.is_printable() ? "printable" : "not printable") +
                   " (" + std::to_string(check.fold_over_faces.size()) + " fold-over faces, " +
                   std::to_string(check.crossings.faces.size()) + " crossing faces, " +
                   std::to_string(check.near_misses.size()) + " near-miss vertices)");
  context.paint_faces();
  context.refresh_selection();
}

std::vector<FacePaint> PrintCheckTool::face_paints(const ToolContext& context) const {
  const StageResult* shown = context.stage.shown();
  if (!shown) return {};
  return job_.face_paints(*shown, context.stage.settings());
}

void PrintCheckTool::draw_section(ToolContext& context) {
  const Session* session = context.sessions.session();
  const bool is_current = session && job_.is_current(*session, context.stage.settings());
  if (ImGui::Button("Check now")) context.actions.run(Action::print_check);
  ImGui::SameLine();
  ImGui::Checkbox("after each change", &job_.is_automatic);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
  double wall = job_.min_wall;
  if (ImGui::InputDouble("minimum wall", &wall, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue))
    job_.min_wall = wall > 0.0 ? wall : 0.0;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("0: twice the offset distance");
  if (job_.is_busy()) ImGui::Text("checking ... %d%%", int(job_.progress() * 100.0));
  const PrintCheckRun* run = job_.last();
  if (!run) {
    if (!job_.is_busy()) ImGui::TextDisabled("not checked yet");
    return;
  }
  draw_verdict(*run, is_current);
  ImGui::PushTextWrapPos(0.0f);  // the sidebar may be narrow
  ImGui::TextDisabled("red: crossings, magenta: fold-overs, orange: too thin");
  ImGui::PopTextWrapPos();
  if (const auto place = draw_places(run->check))
    context.view.frame(job_.place_box(*place), {}, context.layout.viewport);
}

}  // namespace nome::viewer

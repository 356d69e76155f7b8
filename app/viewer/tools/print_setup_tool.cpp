#include "viewer/tools/print_setup_tool.hpp"

#include <imgui.h>

namespace nome::viewer {
namespace {

// The fit: a choice of none, height and largest dimension, and the size in mm.
bool draw_print_fit(PrintPlacementOptions& setup) {
  int fit = int(setup.fit);
  bool is_changed = ImGui::Combo("fit", &fit, "as modelled\0height\0largest dimension\0\0");
  setup.fit = FitTarget(fit);
  if (setup.fit == FitTarget::none) return is_changed;
  if (setup.fit_size <= 0.0) setup.fit_size = 60.0, is_changed = true;
  double size = setup.fit_size;
  if (ImGui::InputDouble("size (mm)", &size, 1.0, 10.0, "%.1f") && size > 0.0) {
    setup.fit_size = size;
    is_changed = true;
  }
  return is_changed;
}

}  // namespace

std::optional<PrintPlacementOptions> draw_print_setup_section(const PrintPlacementOptions& setup,
                                                              std::optional<Index> selected_face) {
  PrintPlacementOptions edited = setup;
  bool is_changed = draw_print_fit(edited);
  int rest = int(edited.rest);
  const bool can_rest_on_face = selected_face.has_value() || edited.rest == RestOn::face;
  const char* rests =
      can_rest_on_face ? "as modelled\0flattest face\0chosen face\0\0" : "as modelled\0flattest face\0\0";
  if (ImGui::Combo("rest on", &rest, rests)) {
    edited.rest = RestOn(rest);
    if (edited.rest == RestOn::face && selected_face) edited.rest_face = *selected_face;
    is_changed = true;
  }
  if (edited.rest == RestOn::face) {
    ImGui::Text("face %u", edited.rest_face);
    if (selected_face && *selected_face != edited.rest_face) {
      ImGui::SameLine();
      if (ImGui::SmallButton("use the selected face")) {
        edited.rest_face = *selected_face;
        is_changed = true;
      }
    }
  } else if (!selected_face) {
    ImGui::TextDisabled("select a face to rest on it");
  }
  ImGui::PushTextWrapPos(0.0f);  // the sidebar may be narrow
  ImGui::TextDisabled("File > Export and `nome export` apply it; saving keeps it");
  ImGui::PopTextWrapPos();
  if (!is_changed || edited == setup) return std::nullopt;
  return edited;
}

void PrintSetupTool::draw_section(ToolContext& context) {
  const scene::Scene* scene = context.sessions.scene();
  if (!scene) {
    ImGui::TextDisabled("open a scene (.nome) to prepare it for printing");
    return;
  }
  const std::vector<Index>& faces = context.selection.faces();
  const std::optional<Index> face = faces.size() == 1 ? std::optional(faces.front()) : std::nullopt;
  if (const auto changed =
          draw_print_setup_section(scene->print_setup().value_or(PrintPlacementOptions{}), face))
    context.sessions.set_print_setup(*changed);
}

std::optional<Mesh> PrintSetupTool::exported(const ToolContext& context, const Mesh& shown) const {
  const scene::Scene* scene = context.sessions.scene();
  if (!scene || !scene->print_setup()) return std::nullopt;
  return placed_for_print(shown, *scene->print_setup());
}

}  // namespace nome::viewer

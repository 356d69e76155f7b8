#include <algorithm>
#include <cmath>
#include <utility>

#include <imgui.h>

#include "viewer/window.hpp"

// The panels in their places: the style for the screen, the layout of the sidebars, the log and the
// viewport, and what each panel shows.
namespace nome::viewer {
namespace {

// Limits of a sidebar dragged by its edge (at content scale 1).
constexpr double min_sidebar_width = 180.0;
constexpr double max_sidebar_width = 900.0;

// The width the user dragged a sidebar to, at content scale 1; the old one when the edge did not move
// (a narrow window's shrunk sidebar must not become the remembered width).
double dragged_width(double drawn, double arranged, double remembered, double scale) {
  if (std::abs(drawn - arranged) < 0.5) return remembered;
  return std::clamp(drawn / scale, min_sidebar_width, max_sidebar_width);
}

}  // namespace

void Window::apply_style() {
  const float scale = platform_.content_scale();
  if (scale == style_scale_ && layout_settings_.is_dark == is_style_dark_) return;
  style_scale_ = scale;
  is_style_dark_ = layout_settings_.is_dark;
  ImGuiStyle style;
  if (is_style_dark_)
    ImGui::StyleColorsDark(&style);
  else
    ImGui::StyleColorsLight(&style);
  style.PopupRounding = 4.0f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  // The font grows with the screen's scale (from the next frame on, as ImGui takes it then).
  ImGui::GetIO().FontGlobalScale = scale;
}

void Window::arrange_layout() {
  const LayoutChrome chrome{ImGui::GetFrameHeight(), status_bar_height(),
                            ImGui::GetFrameHeight() + 2.0 * ImGui::GetStyle().WindowPadding.y,
                            platform_.content_scale()};
  layout_ = arrange(layout_settings_, platform_.window_size(), chrome);
  is_layout_known_ = true;
  if (is_framing_pending_) {
    is_framing_pending_ = false;
    frame_all();
  }
}

render::PixelRect Window::viewport_pixels() const {
  // Window pixels (cursor units, y down) to framebuffer pixels (GL's, y up): they differ on HiDPI.
  const glm::dvec2 scale = glm::dvec2(platform_.framebuffer_size()) / platform_.window_size();
  const glm::dvec2 low = glm::round(layout_.viewport.origin * scale);
  const glm::dvec2 high = glm::round(layout_.viewport.max() * scale);
  const int height = platform_.framebuffer_size().y;
  return {{int(low.x), height - int(high.y)}, glm::max(glm::ivec2(high - low), glm::ivec2(1))};
}

std::vector<scene::ParameterId> Window::selection_parameters(const scene::Scene& scene) const {
  const Mesh* mesh = stage_.shown_mesh();
  if (!mesh || selection_.is_empty()) return {};
  std::vector<Index> vertices = selection_.vertices();
  for (Index f : selection_.faces())
    for (Index v : mesh->face_vertices(f)) vertices.push_back(v);
  // Computed stages have no names: their vertices depend on no slider that a name could tell.
  const auto& names = mesh->vertex_names();
  std::vector<scene::ParameterId> parameters;
  for (Index v : vertices)
    if (v < names.size() || rims_.is_rim(v))
      for (scene::ParameterId p : scene.parameters_of_vertex(rims_.name(*mesh, v))) parameters.push_back(p);
  return parameters;
}

double Window::take_scroll(ScrolledPanel panel) {
  return std::exchange(pending_scroll_[std::size_t(panel)], 0.0);
}

void Window::scroll(ScrolledPanel panel, double pixels) {
  pending_scroll_[std::size_t(panel)] += pixels;
  // ImGui moves a panel's content the frame after it is asked: the next command waits for that.
  settle_frames_ = 2;
}

void Window::draw_panels() {
  report_ = {};
  report_.panels.push_back({"viewport", layout_.viewport});
  const MenuContext menu{sessions_.recent(), sessions_.has_session(), sessions_.has_scene(),
                         sessions_.can_undo(), sessions_.can_redo()};
  ImGuiMenuSink menus;
  if (const auto chosen = draw_main_menu(menus, actions_, menu, display_, layout_settings_))
    request_open(*chosen);
  draw_sidebars();
  draw_tool_pane();
  for (const std::unique_ptr<Tool>& tool : tools_) tool->draw_overlay(tool_context_);
  if (const auto place =
          draw_log_panel(log_, layout_.log, layout_settings_.is_log_open, take_scroll(ScrolledPanel::log)))
    show_place(*place);
  report_.panels.push_back({"log", layout_.log});
  draw_status();
  if (panels_.is_help_shown) draw_help_overlay(actions_, panels_.is_help_shown);
  if (stage_.is_busy() && stage_.seconds_running() >= 0.03)
    draw_progress(stage_.seconds_running(), stage_.progress());
  draw_browser();
}

void Window::draw_sidebars() {
  const double scale = platform_.content_scale();
  double width = 0.0;
  if (layout_settings_.is_left_shown) {
    report_.panels.push_back({"controls", layout_.left});
    if (begin_docked_panel("Controls", layout_.left, &width, take_scroll(ScrolledPanel::controls))) {
      draw_tool_sections(ToolSide::left);
      const ControlPanelChanges changes = draw_control_panel(
          actions_, {stage_.settings(), zipper_options_, display_, edit_colors_, sessions_.document(),
                     can_edit(), sessions_.is_parameter_lock_on(), sif_pairing(), sharpness_});
      if (changes.is_selection_changed) refresh_selection();
      if (changes.is_edit_color_changed) paint_faces();
    }
    ImGui::End();
    layout_settings_.left_width =
        dragged_width(width, layout_.left.size.x, layout_settings_.left_width, scale);
  }
  if (!layout_settings_.is_right_shown) return;
  report_.panels.push_back({"parameters", layout_.right});
  ParameterMoves moves;
  if (begin_docked_panel("Parameters", layout_.right, &width, take_scroll(ScrolledPanel::parameters))) {
    if (const StageResult* shown = stage_.shown())
      if (ImGui::CollapsingHeader("Topology", ImGuiTreeNodeFlags_DefaultOpen))
        draw_topology_section(shown->topology, shown_size_);
    draw_tool_sections(ToolSide::right);
    if (const scene::Scene* scene = sessions_.scene()) {
      const bool is_locked = sessions_.are_parameters_locked();
      if (is_locked) ImGui::TextDisabled("locked while editing (Controls > Edit)");
      ImGui::BeginDisabled(is_locked);
      moves = draw_parameter_section(*scene, selection_parameters(*scene), parameters_, report_);
      ImGui::EndDisabled();
    } else
      ImGui::TextDisabled("no sliders: open a scene (.nome)");
  }
  ImGui::End();
  layout_settings_.right_width =
      dragged_width(width, layout_.right.size.x, layout_settings_.right_width, scale);
  sessions_.move_sliders(moves.moves, moves.continues);
}

void Window::draw_tool_pane() {
  const auto tool =
      std::find_if(tools_.begin(), tools_.end(), [](const auto& t) { return !t->pane_title().empty(); });
  if (!layout_settings_.is_pane_shown || tool == tools_.end()) return;
  report_.panels.push_back({"pane", layout_.pane});
  double width = 0.0;
  if (begin_docked_panel((*tool)->pane_title().c_str(), layout_.pane, &width))
    (*tool)->draw_pane(tool_context_);
  ImGui::End();
  layout_settings_.pane_width =
      dragged_width(width, layout_.pane.size.x, layout_settings_.pane_width, platform_.content_scale());
}

void Window::draw_status() {
  const StageResult* shown = stage_.shown();
  std::optional<StatusLine> status;
  if (sessions_.has_session() && shown)
    status = StatusLine{sessions_.path().filename().string(),
                        sessions_.is_modified(),
                        shown->stage,
                        shown->mesh->num_vertices(),
                        shown->mesh->num_faces(),
                        shown_size_,
                        {}};
  if (status)
    for (const std::unique_ptr<Tool>& tool : tools_)
      if (std::string note = tool->status_text(tool_context_); !note.empty())
        status->notes.push_back(std::move(note));
  draw_status_bar(status, log_);
}

void Window::draw_browser() {
  const auto chosen = browser_.draw();
  if (!chosen) return;
  if (browser_purpose_ == Action::open)
    request_open(*chosen);
  else if (browser_purpose_ == Action::save_as) {
    if (sessions_.save_logged(*chosen)) platform_.offer_saved_file(*chosen);
  } else if (export_mesh(*chosen)) {
    platform_.offer_saved_file(*chosen);
  }
}

}  // namespace nome::viewer

#include <imgui.h>

#include "viewer/window.hpp"

// Stage settings and colour changes as steps of the undo history (slider moves and edits are the
// session controller's own steps).
namespace nome::viewer {
namespace {

bool same_colors(const render::DisplaySettings& a, const render::DisplaySettings& b) {
  return a.front_color == b.front_color && a.back_color == b.back_color &&
         a.selection_color == b.selection_color && a.rim_color == b.rim_color && a.background == b.background;
}

}  // namespace

Window::ViewState Window::view_state() const {
  return {stage_.settings(), display_, edit_colors_};
}

void Window::restore(const ViewState& state) {
  stage_.settings() = state.settings;
  display_.front_color = state.colors.front_color;
  display_.back_color = state.colors.back_color;
  display_.selection_color = state.colors.selection_color;
  display_.background = state.colors.background;
  display_.rim_color = state.colors.rim_color;
  edit_colors_ = state.edit_colors;
  recorded_ = view_state();
  refresh_selection();
  paint_faces();
}

void Window::record_view_state() {
  const bool is_held = ImGui::IsAnyItemActive();
  const ViewState now = view_state();
  const bool is_same = now.settings == recorded_.settings && same_colors(now.colors, recorded_.colors) &&
                       now.edit_colors.temporary == recorded_.edit_colors.temporary &&
                       now.edit_colors.consolidated == recorded_.edit_colors.consolidated;
  if (!is_same && sessions_.has_session()) {
    const ViewState before = recorded_;
    sessions_.push_step({[this, before] { return restore(before), true; },
                         [this, now] { return restore(now), true; }, "view settings"},
                        is_settings_drag_open_ && is_held);
    is_settings_drag_open_ = is_held;
  }
  recorded_ = now;
  if (!is_held) is_settings_drag_open_ = false;
}

}  // namespace nome::viewer

#include "viewer/tools/print_check_tool.hpp"
#include "viewer/window.hpp"

namespace nome::viewer {

// The print check in this window (issue 17): its actions, its job's results and its marks.

void Window::bind_print_check_actions() {
  actions_.bind(Action::print_check, [this] {
    const Session* session = sessions_.session();
    if (!session) {
      log_.warning("print check: open a scene or mesh first");
      return false;
    }
    print_check_.request(*session, stage_.settings());
    return true;
  });
  actions_.bind(Action::next_print_place, [this] {
    if (!print_check_.last() || print_check_.last()->check.places.empty()) {
      log_.warning("print check: no places to frame (run the check first)");
      return false;
    }
    const std::size_t place = print_check_.next_place();
    view_.frame(print_check_.place_box(place), {}, layout_.viewport);
    return true;
  });
}

void Window::update_print_check() {
  const Session* session = sessions_.session();
  if (!session) return;
  try {
    if (!print_check_.update(stage_, *session, platform_.now())) return;
  } catch (const std::exception& e) {
    log_.error("print check: " + std::string(e.what()));
    return;
  }
  const PrintCheck& check = print_check_.last()->check;
  log_.info("print check: " + std::string(check.is_printable() ? "printable" : "not printable") + " (" +
            std::to_string(check.fold_over_faces.size()) + " fold-over faces, " +
            std::to_string(check.crossings.faces.size()) + " crossing faces, " +
            std::to_string(check.near_misses.size()) + " near-miss vertices)");
  paint_faces();
  refresh_selection();
}

void Window::paint_faces() {
  const StageResult* shown = stage_.shown();
  if (!shown) return;
  show_face_colors(renderer_, *shown, edit_colors_, print_check_.face_paints(*shown, stage_.settings()));
}

void Window::draw_print_check_section() {
  const Session* session = sessions_.session();
  const bool is_current = session && print_check_.is_current(*session, stage_.settings());
  if (const auto place = viewer::draw_print_check_section(actions_, print_check_, is_current))
    view_.frame(print_check_.place_box(*place), {}, layout_.viewport);
}

}  // namespace nome::viewer
